#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/scene/Scene.hpp>

#include <algorithm>
#include <string>

namespace stoa {

void ForwardRenderer::render(const Scene& scene, const Camera& camera, const Program& program, glm::ivec2 size) const {
    STOA_ASSERT(size.x > 0 && size.y > 0, "ForwardRenderer::render(): the viewport must not be empty");
    glViewport(0, 0, size.x, size.y);
    glClearColor(clearColor.r, clearColor.g, clearColor.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);

    program.use();
    program.set("uView", camera.viewMatrix());
    program.set("uProjection", camera.projectionMatrix(static_cast<float>(size.x) / static_cast<float>(size.y)));
    program.set("uCameraPosition", camera.eyePosition());
    program.set("uAmbient", scene.ambient);

    const int directionalCount =
        std::min(static_cast<int>(scene.directionalLights.size()), Scene::kMaxDirectionalLights);
    program.set("uDirectionalLightCount", directionalCount);
    for (int i = 0; i < directionalCount; ++i) {
        const std::string prefix = "uDirectionalLights[" + std::to_string(i) + "].";
        program.set(prefix + "direction", scene.directionalLights[i].direction);
        program.set(prefix + "color", scene.directionalLights[i].color);
    }
    const int pointCount = std::min(static_cast<int>(scene.pointLights.size()), Scene::kMaxPointLights);
    program.set("uPointLightCount", pointCount);
    for (int i = 0; i < pointCount; ++i) {
        const std::string prefix = "uPointLights[" + std::to_string(i) + "].";
        program.set(prefix + "position", scene.pointLights[i].position);
        program.set(prefix + "color", scene.pointLights[i].color);
        program.set(prefix + "attenuation", scene.pointLights[i].attenuation);
    }

    for (const auto& object : scene.objects()) object->draw(program);
}

} // namespace stoa
