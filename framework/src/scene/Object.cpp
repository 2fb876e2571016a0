#include <stoa/camera/Camera.hpp>
#include <stoa/math/Transforms.hpp>
#include <stoa/scene/Object.hpp>

#include <glm/glm.hpp>

namespace stoa {

glm::mat4 Object::modelMatrix() const { return stoa::modelMatrix(position, rotationDegrees, scale); }

glm::mat3 Object::normalMatrix() const { return glm::transpose(glm::inverse(glm::mat3(modelMatrix()))); }

float Object::distanceTo(const Camera& camera) const { return glm::length(camera.eyePosition() - position); }

} // namespace stoa
