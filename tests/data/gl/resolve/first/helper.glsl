// first/helper.glsl: loses to second/helper.glsl for second_only.glsl
const int helperFrom = 1;
