// The per-frame uniforms of the framework's shaders, in one uniform block that
// the renderer fills once per frame (stoa/render/FrameUniforms.hpp mirrors it
// byte for byte, std140). The members keep their uniform names: a shader reads
// uView or uDirectionalLights[i] as before.
#include "common/lights.glsl"

layout(std140) uniform Frame {
    mat4 uView;                    // world -> view
    mat4 uProjection;              // view -> clip
    vec3 uCameraPosition;          // world space
    vec3 uAmbient;                 // I_amb
    int uDirectionalLightCount;    // 0..MAX_DIRECTIONAL_LIGHTS
    int uPointLightCount;          // 0..MAX_POINT_LIGHTS
    DirectionalLight uDirectionalLights[MAX_DIRECTIONAL_LIGHTS];
    PointLight uPointLights[MAX_POINT_LIGHTS];
};
