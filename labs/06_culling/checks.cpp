// Lab 06's property checks; see checks.hpp. Every object of the field turns
// about Y only, and a turn about Y leaves the Y axis where it was: a stretch
// along Y then shows in a row of the model matrix as well as in a column. A
// turn about X moves it, and only the columns still say how far it reaches.

#include "checks.hpp"
#include "lab06.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <string>

namespace lab06 {

stoa::CheckResult checkSphereTurnedAboutX() {
    // A column 3 times as tall as it is wide, turned 40 degrees about X and moved.
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(4.0f, 1.0f, -6.0f)) *
                            glm::rotate(glm::mat4(1.0f), glm::radians(40.0f), glm::vec3(1.0f, 0.0f, 0.0f)) *
                            glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 3.0f, 1.0f));
    const stoa::BoundingSphere local{glm::vec3(0.0f, 0.5f, 0.0f), 1.0f};
    const stoa::BoundingSphere world = stoa::worldBoundingSphere(local, model);
    const std::string what = "worldBoundingSphere() of a sphere of radius 1 under a model that stretches Y by 3 and "
                             "turns 40 degrees about X";

    const glm::vec3 centre(model * glm::vec4(local.center, 1.0f));
    if (glm::length(world.center - centre) > 1e-3f)
        return stoa::CheckResult::fail(what + ": the centre is " + stoa::checkVector(world.center) + ", expected " +
                                       stoa::checkVector(centre) + ", the object's centre carried by the whole model matrix "
                                       "(docs: A sphere in world space)");

    // The points of the object's sphere along its axes and diagonals: each must land inside.
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) {
                if (x == 0 && y == 0 && z == 0) continue;
                const glm::vec3 onSphere = local.center + local.radius * glm::normalize(glm::vec3(x, y, z));
                const glm::vec3 landed(model * glm::vec4(onSphere, 1.0f));
                const float distance = glm::length(landed - world.center);
                if (distance > world.radius + 1e-3f)
                    return stoa::CheckResult::fail(
                        what + ": its radius is " + stoa::checkNumber(world.radius, 3) + ", but the point " + stoa::checkVector(onSphere) +
                        " of the object's sphere lands " + stoa::checkNumber(distance, 3) +
                        " from the centre, outside it. The radius grows by the longest column of the model's upper "
                        "3 x 3, how far one step along an object axis goes (docs: A sphere in world space)");
            }
    if (world.radius > 3.0f * 1.001f)
        return stoa::CheckResult::fail(what + ": its radius is " + stoa::checkNumber(world.radius, 3) +
                                       ", larger than needed: the longest column is 3 long, so 3 holds the object "
                                       "(docs: A sphere in world space)");
    return stoa::CheckResult::pass("a sphere stretched along Y and turned about X still holds every point of the "
                                   "object's sphere, and is no larger than the longest column says");
}

} // namespace lab06
