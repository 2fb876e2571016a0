// Lab 06's functions into the framework's student-code table (StudentCode.hpp),
// as a renderer asks for them (CourseRenderer, ForwardRenderer::cull): the
// program of every lab that links lab 06's code calls this at start-up.

#include "lab06.hpp"

#include <stoa/camera/Camera.hpp>
#include <stoa/core/StudentCode.hpp>

#include <memory>
#include <utility>

namespace lab06 {

void handOver(stoa::StudentCode& code) {
    // The planes once per view-projection matrix, not once per object.
    auto planes = std::make_shared<std::pair<glm::mat4, stoa::Frustum>>(glm::mat4(0.0f), stoa::Frustum{});
    code.culling.isVisible = [planes](const stoa::BoundingSphere& sphere, const glm::mat4& viewProjection) {
        if (planes->first != viewProjection) *planes = {viewProjection, stoa::frustumPlanes(viewProjection)};
        return stoa::sphereInFrustum(planes->second, sphere);
    };
    code.culling.levelOf = [](const stoa::BoundingSphere& sphere, const stoa::Camera& camera, int viewportHeight,
                              int levelCount) {
        const float quality = stoa::lodQuality(sphere, camera.eyePosition(), camera.fovYDegrees(), viewportHeight);
        return stoa::levelOfDetail(quality, levelCount);
    };
}

} // namespace lab06
