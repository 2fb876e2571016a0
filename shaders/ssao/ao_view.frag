#version 330 core
// Lab 09's occlusion views: one channel (.r) as grey.

uniform sampler2D uImage;

out vec4 fragColor;

void main() {
    fragColor = vec4(vec3(texelFetch(uImage, ivec2(gl_FragCoord.xy), 0).r), 1.0);
}
