// second/shared.glsl: loses to first/shared.glsl
const int sharedFrom = 2;
