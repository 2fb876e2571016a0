// What lab 09's ssao.glsl may use besides its arguments: the kernel, the
// radius and bias, the noise tile, and the depth of the scene at any point of
// the picture. Include after deferred/gbuffer_read.glsl. No student code here.

#define MAX_KERNEL_SIZE 64

uniform vec3 uKernel[MAX_KERNEL_SIZE];   // ssaoKernel(): the hemisphere around +z
uniform int uKernelSize;
uniform float uRadius;                   // view-space metres
uniform float uBias;                     // view-space metres
uniform sampler2D uNoise;                // ssaoNoise(): 4 x 4, nearest

// The view-space z of the surface the G-buffer holds at texture coordinates
// uv (clamped to the picture); far away (-1e6) where nothing was drawn.
float sceneDepthAt(vec2 uv) {
    ivec2 size = ivec2(uViewport);
    ivec2 pixel = clamp(ivec2(uv * uViewport), ivec2(0), size - 1);
    float depth = texelFetch(uDepth, pixel, 0).r;
    if (depth >= 1.0) return -1e6;
    return viewPositionFromDepth(uv, depth, uInverseProjection).z;
}
