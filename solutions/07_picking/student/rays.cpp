// Lab 07, part 1: rays through pixels, and what they hit.
// Read docs/labs/07_picking.md, "A ray through a pixel", "The slab test" and
// "Ray and triangle" first. The app casts one ray per pixel of the ray-cast
// cases, and one through the clicked pixel when you pick.

#include "lab07.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

Ray rayThroughPixel(const glm::vec2& pixel, const glm::ivec2& viewport, const glm::mat4& inverseViewProjection) {
    // Pixel to normalized device coordinates: x from -1 (left) to 1, y from 1
    // (top) to -1, since pixel rows run down and NDC's y runs up.
    const glm::vec2 ndc(2.0f * pixel.x / static_cast<float>(viewport.x) - 1.0f,
                        1.0f - 2.0f * pixel.y / static_cast<float>(viewport.y));
    glm::vec4 nearPoint = inverseViewProjection * glm::vec4(ndc, -1.0f, 1.0f);
    glm::vec4 farPoint = inverseViewProjection * glm::vec4(ndc, 1.0f, 1.0f);
    nearPoint /= nearPoint.w;
    farPoint /= farPoint.w;
    return makeRay(glm::vec3(nearPoint), glm::normalize(glm::vec3(farPoint - nearPoint)));
}

bool rayHitsBox(const Ray& ray, const Aabb& box, float tMax, float& tEntry) {
    // Each axis' slab between its two planes is crossed from t1 to t2 (in
    // either order); the ray is in the box where it is in all three slabs.
    const glm::vec3 t1 = (box.min - ray.origin) * ray.inverseDirection;
    const glm::vec3 t2 = (box.max - ray.origin) * ray.inverseDirection;
    const glm::vec3 nearest = glm::min(t1, t2);
    const glm::vec3 farthest = glm::max(t1, t2);
    const float enter = std::max({nearest.x, nearest.y, nearest.z, 0.0f});
    const float leave = std::min({farthest.x, farthest.y, farthest.z, tMax});
    if (enter > leave) return false;
    tEntry = enter;
    return true;
}

bool rayHitsTriangle(const Ray& ray, const Triangle& triangle, Hit& hit) {
    constexpr float kEpsilon = 1e-7f;
    const glm::vec3 edge1 = triangle.p1 - triangle.p0;
    const glm::vec3 edge2 = triangle.p2 - triangle.p0;
    const glm::vec3 p = glm::cross(ray.direction, edge2);
    const float determinant = glm::dot(edge1, p);
    if (std::abs(determinant) < kEpsilon) return false;   // the ray runs along the triangle's plane
    const float inverse = 1.0f / determinant;
    const glm::vec3 s = ray.origin - triangle.p0;
    const float u = glm::dot(s, p) * inverse;
    if (u < 0.0f || u > 1.0f) return false;
    const glm::vec3 q = glm::cross(s, edge1);
    const float v = glm::dot(ray.direction, q) * inverse;
    if (v < 0.0f || u + v > 1.0f) return false;
    const float t = glm::dot(edge2, q) * inverse;
    if (t <= 1e-5f || t >= hit.t) return false;
    hit.t = t;
    hit.u = u;
    hit.v = v;
    return true;
}

} // namespace stoa
