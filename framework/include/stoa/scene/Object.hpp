#pragma once
// Something placed in the world: a position, a rotation and a scale, from which
// its model matrix follows (lab 01's modelMatrix()), optionally relative to a
// parent object, so that a hierarchy of objects moves together.
//
// Subclasses say what they draw (addDraws(): items of a DrawList) and how
// large they are (localBounds()); renderers do the drawing. Override what an
// object type needs: a group node draws nothing, a mesh adds one item, a
// special object sets extra uniforms in setDrawUniforms().

#include <stoa/geometry/Bounds.hpp>
#include <stoa/scene/DrawList.hpp>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace stoa {

class Camera;
class Program;

class Object {
public:
    virtual ~Object() = default;

    std::string name;
    glm::vec3 position{0.0f};          // parent space (world space without a parent)
    glm::vec3 rotationDegrees{0.0f};   // about X, then Y, then Z (see localMatrix())
    glm::vec3 scale{1.0f};

    /// Makes this object's transform relative to `parent` (nullptr: to the
    /// world). The parent must outlive this object (objects of one Scene do)
    /// and must not be this object or one of its descendants (asserted).
    void setParent(const Object* parent);
    const Object* parent() const { return m_parent; }

    /// Object -> parent space: stoa::modelMatrix(position, rotationDegrees, scale).
    glm::mat4 localMatrix() const;
    /// Object -> world: the parent's modelMatrix() times localMatrix().
    glm::mat4 modelMatrix() const;
    /// Transforms normals to world space: the inverse transpose of the model
    /// matrix's upper 3x3, so non-uniform scales keep normals perpendicular.
    glm::mat3 normalMatrix() const;
    /// Distance from the camera's eye to this object's origin, in world units.
    float distanceTo(const Camera& camera) const;

    /// The object's extent in object space; none for an object that draws
    /// nothing (a group node). MeshObject: its mesh's.
    virtual std::optional<Bounds> localBounds() const { return std::nullopt; }
    /// localBounds() carried into world space by modelMatrix().
    std::optional<Bounds> worldBounds() const;

    /// Adds what this object draws to `list` (nothing by default).
    virtual void addDraws(DrawList& list) const { (void)list; }
    /// Sets the uniforms of `program` this object type needs beyond those of
    /// a DrawItem (lab 04's normal map), just before each of its items draws.
    virtual void setDrawUniforms(const Program& program) const { (void)program; }

    /// Draws this object's items with `program`, which this makes current:
    /// uModel, uNormalMatrix, the material and its maps, then the mesh. For a
    /// pass that draws objects one by one (lab 05's depth pass); renderers
    /// draw whole DrawLists.
    void draw(const Program& program) const;

private:
    const Object* m_parent = nullptr;
};

} // namespace stoa
