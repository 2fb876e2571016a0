// Lab 03: texture coordinates and texture maps. Read docs/labs/03_meshes.md.
// shaders/textured/textured.vert calls vertexUv(); shaders/textured/textured.frag
// calls surfaceNormal() and mappedMaterial(), then lights the fragment with
// your lab-02 directionalLight() and pointLight().
#include "common/lights.glsl"

// Vertex stage: the uv the rasterizer interpolates for the fragments.
// uvMesh is the vertex's uv from the OBJ file (v up, the OpenGL convention);
// Texture2D uploads images so that v = 0 is their bottom row.
vec2 vertexUv(vec2 uvMesh) {
    // TODO(lab03): pass the texture coordinates through (docs: "Texture coordinates").
    return STOA_NOT_IMPLEMENTED(vec2(0.0));
}

// Fragment stage: the unit normal to shade with, from the normal interpolated
// between the vertices (world space, after the normal matrix).
vec3 surfaceNormal(vec3 normalInterpolated) {
    // TODO(lab03): neither the normal matrix nor interpolation keeps length 1 (docs: "Normals after a scale").
    return STOA_NOT_IMPLEMENTED(vec3(0.0, 1.0, 0.0));
}

// Fragment stage: the material at this fragment. Where a map is present its
// texel multiplies the material's colour: k_d = diffuse map (rgb) * Kd,
// k_s = specular map (grey, read from .r) * Ks. Ambient follows k_d's map.
Material mappedMaterial(Material material, vec2 uv, sampler2D diffuseMap, bool hasDiffuseMap,
                        sampler2D specularMap, bool hasSpecularMap) {
    // TODO(lab03): sample the maps where they are present (docs: "Sampling the maps").
    return STOA_NOT_IMPLEMENTED(material);
}
