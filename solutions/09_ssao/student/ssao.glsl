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
    return texelFetch(noise, pixel % 4, 0).xyz;
}

// The tangent frame that takes the kernel's +z hemisphere to the one around
// N, turned about N by the random vector r (Gram-Schmidt): columns T, B, N.
mat3 kernelBasis(vec3 N, vec3 r) {
    vec3 T = normalize(r - N * dot(r, N));
    vec3 B = cross(N, T);
    return mat3(T, B, N);
}

// 1 - the share of the kernel's samples around P (radius uRadius) that lie
// behind the surface the depth buffer sees, each weighted by the range check.
float ambientOcclusion(vec3 P, mat3 basis) {
    float occlusion = 0.0;
    for (int i = 0; i < uKernelSize; ++i) {
        vec3 S = P + basis * uKernel[i] * uRadius;
        vec4 clip = uProjection * vec4(S, 1.0);
        vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
        float sceneZ = sceneDepthAt(uv);
        float rangeCheck = smoothstep(0.0, 1.0, uRadius / abs(P.z - sceneZ));
        occlusion += (sceneZ >= S.z + uBias ? 1.0 : 0.0) * rangeCheck;
    }
    return 1.0 - occlusion / float(uKernelSize);
}

// The mean of the 4 x 4 pixels around `pixel` (offsets -2..1 on each axis),
// those outside the picture left out: one noise tile's worth, so its pattern
// averages away.
float blurAmbientOcclusion(sampler2D ao, ivec2 pixel) {
    ivec2 size = textureSize(ao, 0);
    float sum = 0.0;
    float count = 0.0;
    for (int y = -2; y < 2; ++y)
        for (int x = -2; x < 2; ++x) {
            ivec2 p = pixel + ivec2(x, y);
            if (p.x < 0 || p.y < 0 || p.x >= size.x || p.y >= size.y) continue;
            sum += texelFetch(ao, p, 0).r;
            count += 1.0;
        }
    return sum / count;
}
