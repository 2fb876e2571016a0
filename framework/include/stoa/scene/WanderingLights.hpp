#pragma once
// Many small point lights drifting over the Acropolis at night (labs 08-09):
// each one circles its own spot on a seeded path, bobbing up and down, in a
// colour of its own. The same seed and time give the same lights on every
// machine (no std:: distributions, whose output the standard leaves open), so
// graded cases can fix both.
//
//   std::vector<PointLight> lights = wanderingLights({256, 7}, 1.5f);   // 256 lights, seed 7, at 1.5 s

#include <stoa/scene/Light.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace stoa {

struct WanderingLightsOptions {
    int count = 256;
    std::uint32_t seed = 1;
    glm::vec3 regionMin{-13.0f, 0.3f, -13.0f};   // where the paths' centres lie, world metres
    glm::vec3 regionMax{13.0f, 2.5f, 13.0f};
    float brightness = 1.0f;   // scales every colour
};

/// The lights at `seconds`: positions on their paths, colours (the brightest
/// channel 0.8..1.6 times `brightness`) and attenuation (1, 1, 5): with a
/// cut-off of 1/64 each reaches between about 3 and 4.5 metres.
std::vector<PointLight> wanderingLights(const WanderingLightsOptions& options, float seconds);

} // namespace stoa
