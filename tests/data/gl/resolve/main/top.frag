/* The top file of the resolution test.
   #include "not_an_include.glsl" inside a comment is ignored. */
#version 330 core
#include "local.glsl"
#include "shared.glsl"
#include "local.glsl"
#include "second_only.glsl"

void main() {}
