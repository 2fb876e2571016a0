#include "FaceTriangulation.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/geometry/ObjLoader.hpp>

#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace stoa::detail {

namespace {

/// Twice the signed area of the 2D triangle (a, b, c); > 0 when counter-clockwise.
double cross2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
}

/// Ear clipping for a non-convex face (at most maxNonConvexFaceCorners
/// corners), in the plane the face's Newell normal is closest to. Each ear
/// keeps the face's winding. Should no ear be found (a self-intersecting
/// face), what remains is fanned, so that no part of a face vanishes.
void clipEars(const std::vector<Corner>& face, const std::vector<glm::dvec2>& points, std::vector<Corner>& out) {
    std::vector<int> remaining(face.size());
    for (std::size_t i = 0; i < face.size(); ++i) remaining[i] = static_cast<int>(i);
    std::size_t start = 0;
    while (remaining.size() > 3) {
        const std::size_t m = remaining.size();
        bool found = false;
        for (std::size_t t = 0; t < m && !found; ++t) {
            const std::size_t i = (start + t) % m;
            const int a = remaining[(i + m - 1) % m], b = remaining[i], c = remaining[(i + 1) % m];
            const glm::dvec2 &pa = points[std::size_t(a)], &pb = points[std::size_t(b)], &pc = points[std::size_t(c)];
            if (!(cross2(pa, pb, pc) > 0.0)) continue;  // a reflex or flat corner is no ear
            bool blocked = false;
            for (const int other : remaining) {
                if (other == a || other == b || other == c) continue;
                const glm::dvec2& p = points[std::size_t(other)];
                if (cross2(pa, pb, p) >= 0.0 && cross2(pb, pc, p) >= 0.0 && cross2(pc, pa, p) >= 0.0) {
                    blocked = true;
                    break;
                }
            }
            if (blocked) continue;
            out.push_back(face[std::size_t(a)]);
            out.push_back(face[std::size_t(b)]);
            out.push_back(face[std::size_t(c)]);
            remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(i));
            start = i == 0 ? 0 : i - 1;
            found = true;
        }
        if (!found) break;
    }
    for (std::size_t k = 1; k + 1 < remaining.size(); ++k) {
        out.push_back(face[std::size_t(remaining[0])]);
        out.push_back(face[std::size_t(remaining[k])]);
        out.push_back(face[std::size_t(remaining[k + 1])]);
    }
}

} // namespace

void triangulate(const std::vector<Corner>& face, const std::vector<glm::vec3>& positions, std::vector<Corner>& out,
                 const std::string& file, int line) {
    const std::size_t n = face.size();
    if (n == 3) {
        out.insert(out.end(), face.begin(), face.end());
        return;
    }
    // A polygon that comes back to a vertex it already passed has no
    // sensible triangles (and "f 1 2 3 1 2 3" used to vanish without a word).
    std::vector<int> sorted(n);
    for (std::size_t i = 0; i < n; ++i) sorted[i] = face[i].position;
    std::sort(sorted.begin(), sorted.end());
    const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
    if (repeated != sorted.end()) {
        throw InputError(file, line, "the face uses vertex " + std::to_string(*repeated + 1) +
                                         " more than once; a polygon must not repeat a corner (split it into "
                                         "faces that do not)");
    }
    auto at = [&](std::size_t i) { return positions[std::size_t(face[i % n].position)]; };
    if (n == 4) {
        const glm::vec3 e02 = at(2) - at(0), e13 = at(3) - at(1);
        const std::size_t order[2][6] = {{0, 1, 2, 0, 2, 3}, {0, 1, 3, 1, 2, 3}};
        for (std::size_t i : order[glm::dot(e02, e02) < glm::dot(e13, e13) ? 0 : 1]) out.push_back(face[i]);
        return;
    }
    // The face's plane: Newell's normal (in double, so that no float overflows).
    glm::dvec3 normal(0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 p(at(i)), q(at(i + 1));
        normal += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
    }
    const glm::dvec3 size = glm::abs(normal);
    const int drop = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const double sign = normal[drop] < 0.0 ? -1.0 : 1.0;
    std::vector<glm::dvec2> points(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 p(at(i));
        // (y, z), (z, x), (x, y): counter-clockwise seen along the normal when sign > 0.
        points[i] = glm::dvec2(p[(drop + 1) % 3], sign * p[(drop + 2) % 3]);
    }
    // Convex: no corner turns against the others by more than `tolerance`
    // (a distance: 1e-4 of the face's extent, or float rounding far from the
    // origin), and the turns add up to one full sweep (not two, as in a star
    // drawn in one stroke). A circle of 100,000 corners written with 4 to 7
    // decimals is convex; a fan of a face this close to convex differs from
    // it by less than the tolerance.
    glm::dvec2 lower = points[0], upper = points[0];
    for (const glm::dvec2& p : points) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    const double extent = std::max(upper.x - lower.x, upper.y - lower.y);
    const double farthest = std::max({std::abs(lower.x), std::abs(lower.y), std::abs(upper.x), std::abs(upper.y)});
    const double tolerance = std::max(extent * 1e-4, farthest * 1e-6);
    bool convex = true;
    double sweep = 0.0;
    for (std::size_t i = 0; i < n && convex; ++i) {
        const glm::dvec2 a = points[i], b = points[(i + 1) % n], c = points[(i + 2) % n];
        const glm::dvec2 e1 = b - a, e2 = c - b;
        const double turn = e1.x * e2.y - e1.y * e2.x;
        // turn / |c - a| is how far b lies on the reflex side of the line from a to c.
        if (turn < -tolerance * glm::length(c - a)) convex = false;
        sweep += std::atan2(turn, glm::dot(e1, e2));
    }
    convex = convex && std::abs(sweep - 2.0 * glm::pi<double>()) < 0.5;
    if (convex) {
        for (std::size_t k = 1; k + 1 < n; ++k) {
            out.push_back(face[0]);
            out.push_back(face[k]);
            out.push_back(face[k + 1]);
        }
        return;
    }
    if (n > static_cast<std::size_t>(maxNonConvexFaceCorners)) {
        throw InputError(file, line, "the face has " + std::to_string(n) + " corners and is not convex; a non-convex "
                                         "face may have at most " + std::to_string(maxNonConvexFaceCorners) +
                                         " corners (split it into smaller faces, or triangulate it when exporting)");
    }
    clipEars(face, points, out);
}

} // namespace stoa::detail
