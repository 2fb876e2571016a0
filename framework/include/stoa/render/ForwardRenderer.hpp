#pragma once
// Draws a scene in one pass per object with one program: clears the bound
// framebuffer, sets the per-frame uniforms, then lets each object draw.
//
// Per-frame uniforms (declared in shaders/common/lights.glsl and the shaders
// that use them): uView, uProjection, uCameraPosition, uAmbient,
// uDirectionalLightCount, uDirectionalLights[i].{direction,color},
// uPointLightCount, uPointLights[i].{position,color,attenuation}.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace stoa {

class Camera;
class Program;
class Scene;

class ForwardRenderer {
public:
    glm::vec3 clearColor{0.05f, 0.06f, 0.08f};

    /// Renders into the framebuffer that is bound, over a viewport of `size` pixels.
    void render(const Scene& scene, const Camera& camera, const Program& program, glm::ivec2 size) const;
};

} // namespace stoa
