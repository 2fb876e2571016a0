// Lab 07, part 1: rays through pixels, and what they hit.
// Read docs/labs/07_picking.md, "A ray through a pixel", "The slab test" and
// "Ray and triangle" first. The app casts one ray per pixel of the ray-cast
// cases, and one through the clicked pixel when you pick.

#include "lab07.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

namespace stoa {

Ray rayThroughPixel(const glm::vec2& pixel, const glm::ivec2& viewport, const glm::mat4& inverseViewProjection) {
    // TODO(lab07): the pixel in normalized device coordinates (x from -1 at the
    // left to 1, y from 1 at the TOP to -1: pixel rows run down); the points at
    // NDC z = -1 (near) and z = 1 (far) through inverseViewProjection, each
    // divided by its w; the ray from the near point towards the far one, its
    // direction normalized, made with makeRay() (docs: "A ray through a pixel").
    (void)pixel;
    (void)viewport;
    (void)inverseViewProjection;
    throw NotImplemented("rayThroughPixel()");
}

bool rayHitsBox(const Ray& ray, const Aabb& box, float tMax, float& tEntry) {
    // TODO(lab07): per axis, the ts where the ray crosses the box's two planes,
    // (box.min - origin) * inverseDirection and (box.max - origin) * inverseDirection,
    // sorted into a near and a far one; the ray is inside from the largest near
    // t (at least 0) to the smallest far t (at most tMax) (docs: "The slab test").
    (void)ray;
    (void)box;
    (void)tMax;
    (void)tEntry;
    throw NotImplemented("rayHitsBox()");
}

bool rayHitsTriangle(const Ray& ray, const Triangle& triangle, Hit& hit) {
    // TODO(lab07): Moller-Trumbore: solve origin + t d = (1 - u - v) p0 + u p1 + v p2
    // with Cramer's rule written with cross products; reject a determinant near
    // 0, u or v outside [0, 1], u + v > 1, and t not in (1e-5, hit.t). On a hit
    // set hit.t, hit.u, hit.v (docs: "Ray and triangle").
    (void)ray;
    (void)triangle;
    (void)hit;
    throw NotImplemented("rayHitsTriangle()");
}

} // namespace stoa
