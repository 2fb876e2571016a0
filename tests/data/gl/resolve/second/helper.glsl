// second/helper.glsl: next to second_only.glsl, so it wins over first/helper.glsl
const int helperFrom = 2;
