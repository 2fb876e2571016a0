// main/local.glsl: next to the including file, so it wins
const int localFrom = 0;
