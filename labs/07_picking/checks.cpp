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

namespace lab07 {

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
