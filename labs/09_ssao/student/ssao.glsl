// Lab 09, part 2: the occlusion estimate and the blur, on the GPU. Read
// docs/labs/09_ssao.md. shaders/ssao/ssao.frag calls, for every pixel with a
// surface (view-space position P, normal N):
//   basis = kernelBasis(N, noiseVector(uNoise, pixel));
//   ao = ambientOcclusion(P, basis);
// and shaders/ssao/blur.frag, a second pass, blurAmbientOcclusion(uRawOcclusion, pixel).
// Provided by the files ssao.frag includes before this one
// (shaders/ssao/ssao_inputs.glsl, shaders/common/frame.glsl): uKernel[i]
// (i < uKernelSize), uRadius, uBias, uProjection (view -> clip), and
// sceneDepthAt(uv), the view-space z of the surface the G-buffer holds at
// texture coordinates uv.

// The random vector of this pixel: the 4 x 4 noise tile repeated over the
// picture, one texel per pixel.
vec3 noiseVector(sampler2D noise, ivec2 pixel) {
    // TODO(lab09): texelFetch() the texel of the tile this pixel falls on
    // (docs: "The noise tile").
    return STOA_NOT_IMPLEMENTED(vec3(1.0, 0.0, 0.0));
}

// The tangent frame that takes the kernel's +z hemisphere to the one around
// N, turned about N by the random vector r (Gram-Schmidt): columns T, B, N.
mat3 kernelBasis(vec3 N, vec3 r) {
    // TODO(lab09): T is r without its part along N, normalised; B = N x T
    // (docs: "Orienting the kernel").
    return STOA_NOT_IMPLEMENTED(mat3(1.0));
}

// 1 - the share of the kernel's samples around P (radius uRadius) that lie
// behind the surface the depth buffer sees, each weighted by the range check.
float ambientOcclusion(vec3 P, mat3 basis) {
    // TODO(lab09): for each sample: its view-space position, projected to
    // texture coordinates; compare its z with sceneDepthAt() (plus uBias);
    // weight by the range check (docs: "The occlusion estimate").
    return STOA_NOT_IMPLEMENTED(1.0);
}

// The mean of the 4 x 4 pixels around `pixel` (offsets -2..1 on each axis),
// those outside the picture left out: one noise tile's worth, so its pattern
// averages away.
float blurAmbientOcclusion(sampler2D ao, ivec2 pixel) {
    // TODO(lab09): average texelFetch() over the 16 pixels that lie inside
    // the picture (textureSize()) (docs: "The blur").
    return STOA_NOT_IMPLEMENTED(texelFetch(ao, pixel, 0).r);
}
