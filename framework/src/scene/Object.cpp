#include <stoa/camera/Camera.hpp>
#include <stoa/core/Assert.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/scene/Object.hpp>
#include <stoa/scene/ObjectUniforms.hpp>

#include <glm/glm.hpp>

namespace stoa {

void Object::setParent(const Object* parent) {
    for (const Object* ancestor = parent; ancestor; ancestor = ancestor->m_parent)
        STOA_ASSERT(ancestor != this, "Object::setParent(): the parent is this object or one of its descendants; "
                                      "a hierarchy of objects must not loop.");
    m_parent = parent;
}

glm::mat4 Object::localMatrix() const { return studentCode().transforms.modelMatrix(position, rotationDegrees, scale); }

glm::mat4 Object::modelMatrix() const {
    return m_parent ? m_parent->modelMatrix() * localMatrix() : localMatrix();
}

glm::mat3 Object::normalMatrix() const { return glm::transpose(glm::inverse(glm::mat3(modelMatrix()))); }

float Object::distanceTo(const Camera& camera) const {
    const glm::vec3 origin = m_parent ? glm::vec3(m_parent->modelMatrix() * glm::vec4(position, 1.0f)) : position;
    return glm::length(camera.eyePosition() - origin);
}

std::optional<Bounds> Object::worldBounds() const {
    const std::optional<Bounds> local = localBounds();
    if (!local) return std::nullopt;
    return transformed(*local, modelMatrix());
}

void Object::draw(const Program& program) const {
    DrawList items;
    addDraws(items);
    if (items.empty()) return;
    program.use();
    const ObjectUniforms uniforms(program);
    for (const DrawItem& item : items) {
        uniforms.apply(item);   // setDrawUniforms() first, then the item's
        item.mesh->draw();
    }
}


} // namespace stoa
