// first/local.glsl: loses to main/local.glsl
const int localFrom = 1;
