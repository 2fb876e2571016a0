#version 330 core
#include "common/frame.glsl"   // the per-frame uniform block
// Positions only, for one colour (flat.frag): the editor's stencil pick pass
// (colour writes off) and the outline of the selection (the object drawn a
// little larger where the stencil says it is not).

layout(location = 0) in vec3 aPosition;

uniform mat4 uModel;

void main() {
    gl_Position = uProjection * uView * (uModel * vec4(aPosition, 1.0));
}
