// Lab 05: the first pass, the scene's depth seen from the light.
// Read docs/labs/05_shadows.md, "The two passes".

#include <stoa/core/NotImplemented.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include "lab05.hpp"
#include <stoa/scene/Scene.hpp>

namespace stoa {

void renderShadowPass(const Scene& scene, const Framebuffer& shadowMap, const Program& depthProgram,
                      const glm::mat4& lightSpaceMatrix) {
    // TODO(lab05): begin a pass (a PassDescription and beginPass()) into the map
    // with its depth cleared, depth test on and face culling off (both faces go
    // into the map), then set uLightSpaceMatrix on depthProgram and let every
    // object draw with it (object->draw(depthProgram) sets uModel).
    (void)scene;
    (void)shadowMap;
    (void)depthProgram;
    (void)lightSpaceMatrix;
    throw NotImplemented("renderShadowPass()");
}

} // namespace stoa
