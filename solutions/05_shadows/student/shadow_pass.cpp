// Lab 05: the first pass, the scene's depth seen from the light.
// Read docs/labs/05_shadows.md, "The two passes".

#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include "lab05.hpp"
#include <stoa/scene/Scene.hpp>

namespace stoa {

void renderShadowPass(const Scene& scene, const Framebuffer& shadowMap, const Program& depthProgram,
                      const glm::mat4& lightSpaceMatrix) {
    PassDescription pass;
    pass.target = &shadowMap;    // the viewport is the whole map
    pass.clear.depth = true;
    pass.state.depth.test = true;
    pass.state.depth.func = GL_LESS;
    // Both faces go into the map: the single-sided floor must be there too, and
    // all the bias is then the shader's, where you can see what it does.
    pass.state.cull = CullMode::None;
    beginPass(pass);

    depthProgram.use();
    depthProgram.set("uLightSpaceMatrix", lightSpaceMatrix);
    for (const auto& object : scene.objects()) object->draw(depthProgram);
}

} // namespace stoa
