#version 330 core
#include "07_picking/student/id_buffer.glsl"
// Lab 07's selection outline, a pass over the whole picture after the scene:
// the student's outlineAt() on the ID buffer says where; elsewhere the picture
// stays as it is. Drawn over the viewport with basic/image.vert.

uniform usampler2D uIds;
uniform uint uSelected;
uniform int uRadius;
uniform vec3 uOutlineColor;

out vec4 fragColor;

void main() {
    if (outlineAt(uIds, ivec2(gl_FragCoord.xy), uSelected, uRadius) < 0.5) discard;
    fragColor = vec4(uOutlineColor, 1.0);
}
