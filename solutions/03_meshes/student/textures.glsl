// Lab 03: texture coordinates and texture maps. Read docs/labs/03_meshes.md.
// shaders/textured/textured.vert calls vertexUv(); shaders/textured/textured.frag
// calls surfaceNormal() and mappedMaterial(), then lights the fragment with
// your lab-02 directionalLight() and pointLight().
#include "common/lights.glsl"

// Vertex stage: the uv the rasterizer interpolates for the fragments.
// uvMesh is the vertex's uv from the OBJ file (v up, the OpenGL convention);
// Texture2D uploads images so that v = 0 is their bottom row.
vec2 vertexUv(vec2 uvMesh) {
    return uvMesh;
}

// Fragment stage: the unit normal to shade with, from the normal interpolated
// between the vertices (world space, after the normal matrix).
vec3 surfaceNormal(vec3 normalInterpolated) {
    return normalize(normalInterpolated);
}

// Fragment stage: the material at this fragment. Where a map is present its
// texel multiplies the material's colour: k_d = diffuse map (rgb) * Kd,
// k_s = specular map (grey, read from .r) * Ks. Ambient follows k_d's map.
Material mappedMaterial(Material material, vec2 uv, sampler2D diffuseMap, bool hasDiffuseMap,
                        sampler2D specularMap, bool hasSpecularMap) {
    Material mapped = material;
    if (hasDiffuseMap) {
        vec3 texel = texture(diffuseMap, uv).rgb;
        mapped.diffuse = texel * material.diffuse;
        mapped.ambient = texel * material.ambient;
    }
    if (hasSpecularMap) mapped.specular = texture(specularMap, uv).r * material.specular;
    return mapped;
}
