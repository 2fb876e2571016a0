#version 330 core
#include "07_picking/student/id_buffer.glsl"
// Lab 07's ID pass: the object's 32-bit id, packed by the student's
// packObjectId() into the four bytes of a GL_RGBA8UI target. 0 is the
// background (the clear value).

uniform uint uObjectId;

out uvec4 fragId;

void main() {
    fragId = packObjectId(uObjectId);
}
