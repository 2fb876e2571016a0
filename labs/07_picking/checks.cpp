// Lab 07's property checks; see checks.hpp. The graded pictures cast every ray
// from the camera at boxes in front of it, where a slab test with the wrong
// entry distance still finds the same nearest triangle; this table asks for the
// entry distance itself.

#include "checks.hpp"
#include "lab07.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace lab07 {

namespace {

// A small triangle whose centroid is at x, with y and z in [0, 1) from a fixed
// sequence: the same triangles every run.
struct TriangleMaker {
    stoa::CheckRandom random{20261129u};
    stoa::Triangle at(float x) {
        const float y = random.next(), z = random.next();
        return {{x - 0.05f, y, z}, {x + 0.05f, y, z}, {x, y + 0.1f, z + 0.05f}};
    }
};

int trianglesUnder(const stoa::Bvh& bvh, int node) {
    const stoa::BvhNode& n = bvh.nodes[static_cast<std::size_t>(node)];
    if (n.count > 0) return n.count;
    return trianglesUnder(bvh, n.first) + trianglesUnder(bvh, n.first + 1);
}

// The root's split as the two children's triangle counts, smaller first; empty
// when the root is a leaf.
std::string rootSplit(const stoa::Bvh& bvh) {
    if (bvh.nodes.empty() || bvh.nodes[0].count > 0) return "no split (the root is a leaf)";
    const int a = trianglesUnder(bvh, bvh.nodes[0].first), b = trianglesUnder(bvh, bvh.nodes[0].first + 1);
    return std::to_string(std::min(a, b)) + " | " + std::to_string(std::max(a, b));
}

} // namespace

stoa::CheckResult checkBvhCheapestSplit() {
    struct Layout {
        const char* what;
        std::vector<float> xs;   // the centroids' x
        const char* expected;
        const char* why;
    };
    TriangleMaker maker;
    // 16 triangles within a metre, one 50 m away: the cheapest plane leaves it alone.
    std::vector<float> outlier;
    for (int i = 0; i < 16; ++i) outlier.push_back(0.06f * static_cast<float>(i));
    outlier.push_back(50.0f);
    // 11 triangles one per bin (12 bins over x = 0 to 12) and 30 in the last bin:
    // the cheapest plane is the last one, between bins 10 and 11.
    std::vector<float> lastPlane;
    for (int i = 0; i < 11; ++i) lastPlane.push_back(0.5f + static_cast<float>(i));
    for (int i = 0; i < 30; ++i) lastPlane.push_back(11.4f + 0.2f * static_cast<float>(i) / 29.0f);
    lastPlane.front() = 0.0f;   // the centroids' box from x = 0
    lastPlane.back() = 12.0f;   // to x = 12: bins one metre wide
    // Five triangles near x = 0, one at x = 4.4 and three near x = 12: the lone one
    // joins the three, whose child then spans 7.7 m, since the other plane gives
    // six triangles a child 4.5 m long (the right-hand count matters as much as the left).
    std::vector<float> loneMiddle = {0.0f, 0.05f, 0.1f, 0.15f, 0.2f, 4.4f, 11.8f, 11.9f, 12.0f};
    const Layout layouts[] = {
        {"16 triangles within a metre and one 50 m away along x", outlier, "1 | 16",
         "the cheapest plane leaves the far triangle alone in a child of one"},
        {"11 triangles one a metre from x = 0 to 10.5 and 30 within x = 11.4 to 12", lastPlane, "11 | 30",
         "the cheapest of the bins - 1 planes is the last one, between the last two bins"},
        {"five triangles near x = 0, one at x = 4.4 and three near x = 12", loneMiddle, "4 | 5",
         "the one at x = 4.4 goes with the three: 5 in a small box and 4 over 7.7 m cost less than 6 over 4.5 m and 3 in a small box"},
    };
    for (const Layout& layout : layouts) {
        std::vector<stoa::Triangle> triangles;
        for (const float x : layout.xs) triangles.push_back(maker.at(x));
        const stoa::Bvh bvh = stoa::buildBvh(triangles);
        const std::string split = rootSplit(bvh);
        if (split != layout.expected)
            return stoa::CheckResult::fail("buildBvh() of " + std::string(layout.what) + " splits the root into " + split +
                                           " triangles; expected " + layout.expected + ": " + layout.why +
                                           " (12 bins, C_t = C_i = 1). Try every plane between two bins on each "
                                           "axis, a child of one triangle included, and keep the cheapest "
                                           "(docs: Where to split)");
    }
    return stoa::CheckResult::pass("buildBvh() splits the root at the cheapest plane: a far triangle alone, the "
                                   "last plane between the bins, and a lone triangle joining the group of three");
}

stoa::CheckResult checkSlabTestTable() {
    const float infinity = std::numeric_limits<float>::infinity();
    const stoa::Aabb cube{glm::vec3(-1.0f), glm::vec3(1.0f)};
    const stoa::Aabb away{glm::vec3(2.0f, 1.0f, -6.0f), glm::vec3(4.0f, 3.0f, -5.0f)};
    const glm::vec3 slant = glm::normalize(glm::vec3(1.0f, 0.1f, 0.0f));
    struct Row {
        const char* what;
        glm::vec3 origin, direction;
        stoa::Aabb box;
        float tMax;
        bool hits;
        float entry;
    };
    const Row rows[] = {
        {"along -z at the unit cube", {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, infinity, true, 4.0f},
        {"the same ray, stopped at t = 3.5 before the cube", {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, 3.5f, false, 0.0f},
        {"the same ray, stopped at t = 4.5 inside the cube", {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, 4.5f, true, 4.0f},
        {"away from the cube, which is behind it", {0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 1.0f}, cube, infinity, false, 0.0f},
        {"from inside the cube", {0.2f, 0.3f, 0.0f}, glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)), cube, infinity, true, 0.0f},
        {"slanted, entering through x = -1", {-3.0f, 0.5f, 0.25f}, slant, cube, infinity, true, 2.0f / slant.x},
        {"along -x, entering through x = 1", {5.0f, 0.2f, 0.1f}, {-1.0f, 0.0f, 0.0f}, cube, infinity, true, 4.0f},
        {"parallel to the y slab, inside it", {0.0f, 0.5f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, infinity, true, 4.0f},
        {"parallel to the y slab, outside it", {0.0f, 2.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, infinity, false, 0.0f},
        {"past a corner of the cube", {3.0f, 3.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, cube, infinity, false, 0.0f},
        {"along -z at a box away from the origin", {3.0f, 2.0f, 4.0f}, {0.0f, 0.0f, -1.0f}, away, infinity, true, 9.0f},
        {"along +y at a box away from the origin", {3.5f, -4.0f, -5.5f}, {0.0f, 1.0f, 0.0f}, away, infinity, true, 5.0f},
        {"beside a box away from the origin", {5.0f, 2.0f, 4.0f}, {0.0f, 0.0f, -1.0f}, away, infinity, false, 0.0f},
    };
    for (const Row& row : rows) {
        const stoa::Ray ray = stoa::makeRay(row.origin, row.direction);
        float entry = -7.0f;   // what tEntry held before the call
        const bool hits = stoa::rayHitsBox(ray, row.box, row.tMax, entry);
        const std::string what = "rayHitsBox() for a ray " + std::string(row.what) + " (origin " +
                                 stoa::checkVector(row.origin) + ", direction " + stoa::checkVector(row.direction) +
                                 ", box " + stoa::checkVector(row.box.min) + " to " + stoa::checkVector(row.box.max) + ")";
        if (hits != row.hits)
            return stoa::CheckResult::fail(what + " says " + (hits ? "hit" : "miss") + "; it " +
                                           (row.hits ? "meets" : "misses") + " the box (docs: The slab test)");
        if (hits && !(std::fabs(entry - row.entry) <= 1e-4f))
            return stoa::CheckResult::fail(what + " set tEntry to " + stoa::checkNumber(entry, 4) + "; the ray enters at t = " +
                                           stoa::checkNumber(row.entry, 4) +
                                           " (t_enter = max(0, the largest of the slabs' entries); set tEntry on a hit) "
                                           "(docs: The slab test)");
    }
    return stoa::CheckResult::pass("rayHitsBox() gives the right hit or miss and entry distance for 13 rays and boxes");
}

} // namespace lab07
