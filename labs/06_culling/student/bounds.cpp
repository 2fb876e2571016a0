// Lab 06, part 1: bounding spheres, in object space and in world space.
// Read docs/labs/06_culling.md, "Bounding volumes", first. The app computes a
// mesh's sphere once, then carries it into world space for every object that
// uses the mesh, every frame: the culling tests and the level of detail use
// only this sphere (and the framework's world box).

#include "lab06.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

BoundingSphere meshBoundingSphere(const Mesh& mesh) {
    // TODO(lab06): the axis-aligned box of the vertex positions (component-wise
    // glm::min and glm::max); the sphere's centre is the box's centre, its radius
    // the largest distance from that centre to a vertex. No vertices: {0, 0}
    // (docs: "Bounding volumes").
    (void)mesh;
    throw NotImplemented("meshBoundingSphere()");
}

BoundingSphere worldBoundingSphere(const BoundingSphere& sphere, const glm::mat4& model) {
    // TODO(lab06): the centre is a point: model * vec4(centre, 1). The radius
    // grows with the largest scale: the longest of model's first three columns
    // (each is where a unit axis ends up). docs: "A sphere in world space".
    (void)sphere;
    (void)model;
    throw NotImplemented("worldBoundingSphere()");
}

} // namespace stoa
