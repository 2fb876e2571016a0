// Reading the G-buffer in a lighting pass (labs 08-09): one pixel's albedo,
// specular strength, view-space normal and position, through the student's
// unpackNormal() and viewPositionFromDepth() (08_deferred/student/g_buffer.glsl).
// Include after g_buffer.glsl. No student code here.

uniform sampler2D uAlbedoSpecular;    // GBuffer attachment 0
uniform sampler2D uPackedNormal;      // GBuffer attachment 1
uniform sampler2D uDepth;             // GBuffer depth (window depth in [0, 1])
uniform mat4 uInverseProjection;
uniform vec2 uViewport;               // the G-buffer's size, pixels

struct Surface {
    vec3 albedo;
    float specular;
    vec3 normal;     // view space, unit length
    vec3 position;   // view space
    bool sky;        // nothing drawn here (depth 1)
};

// The view-space position alone (a pass may reject a pixel by its position
// before reading the rest); `sky` is true where nothing was drawn.
vec3 readPosition(ivec2 pixel, out bool sky) {
    float depth = texelFetch(uDepth, pixel, 0).r;
    sky = depth >= 1.0;
    vec2 uv = (vec2(pixel) + 0.5) / uViewport;
    return viewPositionFromDepth(uv, depth, uInverseProjection);
}

// The rest of the pixel's surface, after readPosition().
Surface completeSurface(ivec2 pixel, vec3 position, bool sky) {
    Surface surface;
    vec4 albedoSpecular = texelFetch(uAlbedoSpecular, pixel, 0);
    surface.albedo = albedoSpecular.rgb;
    surface.specular = albedoSpecular.a;
    surface.normal = unpackNormal(texelFetch(uPackedNormal, pixel, 0).rg);
    surface.position = position;
    surface.sky = sky;
    return surface;
}

Surface readSurface(ivec2 pixel) {
    bool sky;
    vec3 position = readPosition(pixel, sky);
    return completeSurface(pixel, position, sky);
}
