#include "Sky.hpp"

#include "Noise.hpp"
#include "PortableMath.hpp"
#include "Writers.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace stoa::assets {

namespace {

constexpr int kFaceSize = 128;

// The direction a cube-map look-up sends to (sc, tc) of `face`: the OpenGL
// spec's cube-map table solved for the direction (major axis of length 1).
glm::vec3 faceDirection(int face, float sc, float tc) {
    switch (face) {
    case 0: return {1.0f, -tc, -sc};
    case 1: return {-1.0f, -tc, sc};
    case 2: return {sc, 1.0f, tc};
    case 3: return {sc, -1.0f, -tc};
    case 4: return {sc, -tc, 1.0f};
    default: return {-sc, -tc, -1.0f};
    }
}

glm::vec3 mix(const glm::vec3& a, const glm::vec3& b, float t) { return a + (b - a) * t; }

float smooth(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Linear RGB in [0, 1] of the sky seen along the unit vector `d`.
glm::vec3 skyColor(const glm::vec3& d) {
    const glm::vec3 sun = glm::normalize(glm::vec3(-0.55f, 0.32f, 0.77f));   // low, south-west (+Z is south)
    const glm::vec3 zenith(0.18f, 0.36f, 0.72f), horizon(0.78f, 0.82f, 0.86f);
    const glm::vec3 groundNear(0.45f, 0.38f, 0.29f), groundFar(0.66f, 0.60f, 0.52f);
    glm::vec3 color;
    if (d.y >= 0.0f) {
        // Blue overhead, paler towards the horizon (most of the change low down).
        color = mix(horizon, zenith, smooth(0.0f, 1.0f, std::sqrt(d.y)));
        // Clouds: fractal noise on the plane the ray meets at height 1, thinning to the horizon.
        if (d.y > 0.02f) {
            const float x = d.x / d.y * 1.6f, z = d.z / d.y * 1.6f;
            const float cover = smooth(0.55f, 0.75f, fbm3(x, 0.0f, z, 4, 71U)) * smooth(0.02f, 0.25f, d.y);
            color = mix(color, glm::vec3(0.95f, 0.94f, 0.92f), 0.85f * cover);
        }
    } else {
        color = mix(groundFar, groundNear, smooth(0.0f, 0.6f, -d.y));
    }
    // The sun: a disc and a glow around it (the glow also over the ground's haze).
    const float toSun = std::max(0.0f, glm::dot(d, sun));
    const float glow = static_cast<float>(portableExp(-(1.0 - toSun) * 28.0));
    color = mix(color, glm::vec3(1.0f, 0.92f, 0.75f), 0.55f * glow);
    if (toSun > 0.9994f) color = glm::vec3(1.0f, 0.98f, 0.92f);
    return glm::clamp(color, glm::vec3(0.0f), glm::vec3(1.0f));
}

} // namespace

const std::vector<std::string>& skyFileNames() {
    static const std::vector<std::string> names{"px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"};
    return names;
}

Image skyFace(int face, int size) {
    Image image(size, size, 3);
    for (int row = 0; row < size; ++row) {
        for (int column = 0; column < size; ++column) {
            const float sc = 2.0f * (static_cast<float>(column) + 0.5f) / static_cast<float>(size) - 1.0f;
            const float tc = 2.0f * (static_cast<float>(row) + 0.5f) / static_cast<float>(size) - 1.0f;
            const glm::vec3 color = skyColor(glm::normalize(faceDirection(face, sc, tc)));
            // sRGB-ish encoding with a square root (the course's images are 8-bit sRGB).
            glm::u8vec4 pixel(255);
            for (int c = 0; c < 3; ++c)
                pixel[c] = static_cast<std::uint8_t>(std::lround(std::sqrt(color[c]) * 255.0f));
            image.setPixel(column, row, pixel);
        }
    }
    return image;
}

void generateSky(const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    for (int face = 0; face < 6; ++face)
        writePng(folder / skyFileNames()[static_cast<std::size_t>(face)], skyFace(face, kFaceSize));
}

} // namespace stoa::assets
