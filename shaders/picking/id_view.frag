#version 330 core
#include "07_picking/student/id_buffer.glsl"
// Lab 07's ID buffer in false colour: each id, unpacked by the student's
// unpackObjectId(), gets a colour of its own (a hash of all 32 bits), the
// background black. Drawn over the viewport with basic/image.vert.

uniform usampler2D uIds;

out vec4 fragColor;

vec3 colorOfId(uint id) {
    // An integer hash (the "lowbias32" mixer), so that ids differing in any bit differ in colour.
    id ^= id >> 16u;
    id *= 0x7feb352du;
    id ^= id >> 15u;
    id *= 0x846ca68bu;
    id ^= id >> 16u;
    return 0.25 + 0.75 * vec3(float(id & 0xFFu), float((id >> 8u) & 0xFFu), float((id >> 16u) & 0xFFu)) / 255.0;
}

void main() {
    uint id = unpackObjectId(texelFetch(uIds, ivec2(gl_FragCoord.xy), 0));
    fragColor = vec4(id == 0u ? vec3(0.0) : colorOfId(id), 1.0);
}
