// second/second_only.glsl: found in the second search-path folder
#include "helper.glsl"
const int secondOnly = 2;
