// Lab 11, part 2: dragging along a gizmo's axis. Read docs/labs/11_editor.md,
// "Dragging along an axis", first.

#include "lab11.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/geometric.hpp>

#include <cmath>

namespace stoa {

std::optional<float> closestAxisParameter(const Line& mouseRay, const Line& axis) {
    // TODO(lab11): with unit directions d (ray) and e (axis), the closest
    // points r(t) and a(s) make a segment perpendicular to both lines. Solve
    // those two conditions for s (docs: "The closest point between two
    // lines"); nullopt when the lines are (nearly) parallel.
    (void)mouseRay;
    (void)axis;
    throw NotImplemented("closestAxisParameter()");
}

glm::vec3 dragAlongAxis(const glm::vec3& startPosition, const glm::vec3& axisDirection, const Line& pressRay,
                        const Line& currentRay) {
    // TODO(lab11): the axis runs through startPosition. Move the object along
    // it by how far the closest point moved between pressRay and currentRay.
    (void)startPosition;
    (void)axisDirection;
    (void)pressRay;
    (void)currentRay;
    throw NotImplemented("dragAlongAxis()");
}

} // namespace stoa
