// Lab 11, part 2: dragging along a gizmo's axis. Read docs/labs/11_editor.md,
// "Dragging along an axis", first.

#include "lab11.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace stoa {

std::optional<float> closestAxisParameter(const Line& mouseRay, const Line& axis) {
    // Points r(t) = p + t d on the ray and a(s) = q + s e on the axis (d, e
    // unit): the segment between the closest points is perpendicular to both,
    //   (r(t) - a(s)) . d = 0 and (r(t) - a(s)) . e = 0,
    // two equations in t and s; with b = d . e and w = p - q they give
    //   s = (w . e - b (w . d)) / (1 - b^2).
    const glm::vec3 d = glm::normalize(mouseRay.direction);
    const glm::vec3 e = glm::normalize(axis.direction);
    const float b = glm::dot(d, e);
    const float sineSquared = 1.0f - b * b;
    if (sineSquared < 1e-6f) return std::nullopt;
    const glm::vec3 w = mouseRay.point - axis.point;
    return (glm::dot(w, e) - b * glm::dot(w, d)) / sineSquared;
}

glm::vec3 dragAlongAxis(const glm::vec3& startPosition, const glm::vec3& axisDirection, const Line& pressRay,
                        const Line& currentRay) {
    const Line axis{startPosition, axisDirection};
    const std::optional<float> pressed = closestAxisParameter(pressRay, axis);
    const std::optional<float> now = closestAxisParameter(currentRay, axis);
    if (!pressed || !now) return startPosition;
    return startPosition + (*now - *pressed) * glm::normalize(axisDirection);
}

} // namespace stoa
