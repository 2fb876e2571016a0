#include <stoa/core/Assert.hpp>
#include <stoa/core/HashRandom.hpp>
#include <stoa/scene/WanderingLights.hpp>

#include <glm/glm.hpp>

#include <cmath>

namespace stoa {

namespace {

// A saturated colour of hue h in [0, 1) (HSV with s = 0.75, v = 1).
glm::vec3 hueColor(float h) {
    const glm::vec3 k(1.0f, 2.0f / 3.0f, 1.0f / 3.0f);
    const glm::vec3 p = glm::abs(glm::fract(glm::vec3(h) + k) * 6.0f - 3.0f);
    return glm::mix(glm::vec3(1.0f), glm::clamp(p - 1.0f, 0.0f, 1.0f), 0.75f);
}

} // namespace

std::vector<PointLight> wanderingLights(const WanderingLightsOptions& options, float seconds) {
    STOA_ASSERT(options.count >= 0, "wanderingLights(): count must not be negative");
    HashRandom random(options.seed, 0x7F4A7C15u);
    std::vector<PointLight> lights;
    lights.reserve(static_cast<std::size_t>(options.count));
    for (int i = 0; i < options.count; ++i) {
        const glm::vec3 centre(random.between(options.regionMin.x, options.regionMax.x),
                               random.between(options.regionMin.y, options.regionMax.y),
                               random.between(options.regionMin.z, options.regionMax.z));
        const float radius = random.between(0.5f, 2.0f);          // of the circle, metres
        const float speed = random.between(0.2f, 0.6f);           // radians per second, either way
        const float direction = random.next() < 0.5f ? -1.0f : 1.0f;
        const float phase = random.between(0.0f, 6.2831853f);
        const float bob = random.between(0.0f, 0.4f);             // metres up and down
        const float hue = random.next();
        const float peak = random.between(0.8f, 1.6f) * options.brightness;
        const float angle = phase + direction * speed * seconds;
        PointLight light;
        light.position = centre + glm::vec3(radius * std::cos(angle), bob * std::sin(2.0f * angle), radius * std::sin(angle));
        light.position.y = std::max(light.position.y, 0.15f);
        light.color = hueColor(hue) * peak;
        light.attenuation = glm::vec3(1.0f, 1.0f, 5.0f);
        lights.push_back(light);
    }
    return lights;
}

} // namespace stoa
