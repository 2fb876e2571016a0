#pragma once
// Something placed in the world: a position, a rotation and a scale, from which
// its model matrix follows (lab 01's modelMatrix()). Subclasses decide how it draws.

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace stoa {

class Camera;
class Program;

class Object {
public:
    virtual ~Object() = default;

    std::string name;
    glm::vec3 position{0.0f};          // world units
    glm::vec3 rotationDegrees{0.0f};   // about X, then Y, then Z (see modelMatrix())
    glm::vec3 scale{1.0f};

    /// Object -> world.
    glm::mat4 modelMatrix() const;
    /// Transforms normals to world space: the inverse transpose of the model
    /// matrix's upper 3x3, so non-uniform scales keep normals perpendicular.
    glm::mat3 normalMatrix() const;
    /// Distance from the camera's eye to this object's position, in world units.
    float distanceTo(const Camera& camera) const;

    /// Draws with `program`, which is in use and has the per-frame uniforms set.
    /// Sets the per-object uniforms it needs (uModel, uNormalMatrix, material).
    virtual void draw(const Program& program) const = 0;
};

} // namespace stoa
