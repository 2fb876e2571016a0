#pragma once
// Independent references shared by lab 07's ray tests (RaysTests.cpp) and BVH
// tests (BvhTests.cpp): a ray's intersection with a triangle's plane and its
// barycentric coordinates from signed areas, in double, with how ill-conditioned
// that case is for float; and the text of vectors and rays for failure messages.

#include "lab07.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace stoa::test::picking {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

inline std::string describe(const glm::vec3& v) {
    std::ostringstream out;
    out.precision(9);
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

inline std::string describe(const stoa::Ray& ray) {
    return "origin " + describe(ray.origin) + " direction " + describe(ray.direction);
}

// --- the reference triangle test: the plane, then signed areas, in double -------

struct ReferenceTriangle {
    glm::dvec3 p0, e1, e2, normal;   // normal = e1 x e2
    double normalLength2 = 0.0;
    explicit ReferenceTriangle(const stoa::Triangle& triangle)
        : p0(triangle.p0), e1(glm::dvec3(triangle.p1) - p0), e2(glm::dvec3(triangle.p2) - p0),
          normal(glm::cross(e1, e2)), normalLength2(glm::dot(normal, normal)) {}
};

struct ReferenceHit {
    bool crosses = false;   // the ray's line is not parallel to the plane
    double t = 0.0, u = 0.0, v = 0.0;
    double cosine = 0.0;    // |cos| of the angle between the ray and the normal
    double margin() const { return std::min({u, v, 1.0 - u - v}); }   // > 0 inside, < 0 outside
};

inline ReferenceHit referenceIntersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                       const ReferenceTriangle& triangle) {
    ReferenceHit hit;
    const double denominator = glm::dot(triangle.normal, direction);
    const double scale = std::sqrt(triangle.normalLength2) * glm::length(direction);
    if (scale == 0.0 || std::abs(denominator) <= 1e-12 * scale) return hit;
    hit.crosses = true;
    hit.cosine = std::abs(denominator) / scale;
    hit.t = glm::dot(triangle.normal, triangle.p0 - origin) / denominator;
    const glm::dvec3 w = origin + hit.t * direction - triangle.p0;
    // Areas of the sub-triangles opposite p1 and p2, signed by the normal, over the whole.
    hit.u = glm::dot(glm::cross(w, triangle.e2), triangle.normal) / triangle.normalLength2;
    hit.v = glm::dot(glm::cross(triangle.e1, w), triangle.normal) / triangle.normalLength2;
    return hit;
}

// How many times float's rounding error u, v may carry for this ray and
// triangle: the origin's distance from p0 against the triangle's size, over the
// sine of its corner and the cosine of the ray with its normal (Moller-Trumbore's
// determinant). Thin triangles seen edge-on from afar are ill-conditioned.
inline double conditioning(const glm::dvec3& origin, const glm::dvec3& direction, const ReferenceTriangle& triangle) {
    const double e1 = glm::length(triangle.e1), e2 = glm::length(triangle.e2);
    const double determinant = std::abs(glm::dot(triangle.normal, direction));
    if (determinant == 0.0) return kInfinity;
    return glm::length(origin - triangle.p0) * glm::length(direction) * std::max(e1, e2) / determinant;
}

inline ReferenceHit referenceIntersect(const stoa::Ray& ray, const stoa::Triangle& triangle) {
    return referenceIntersect(glm::dvec3(ray.origin), glm::dvec3(ray.direction), ReferenceTriangle(triangle));
}

} // namespace stoa::test::picking
