#include <stoa/scene/GroundMapMaker.hpp>

#include <stoa/core/HashRandom.hpp>
#include <stoa/geometry/Mesh.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

namespace {

// The example worlds' footprints (the XML files in assets/crowds/ say the same).
constexpr float kAcropolisHalf = 15.0f;
constexpr int kAcropolisTexels = 256;
constexpr float kHillsHalf = 30.0f;
constexpr int kHillsTexels = 128;
constexpr float kHillsHeight = 6.0f;

void dilate(std::vector<std::uint8_t>& blocked, int width, int height, int radius) {
    if (radius <= 0) return;
    std::vector<std::uint8_t> out(blocked.size(), 0);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (!blocked[static_cast<std::size_t>(y) * width + x]) continue;
            for (int dy = -radius; dy <= radius; ++dy) {
                for (int dx = -radius; dx <= radius; ++dx) {
                    if (dx * dx + dy * dy > radius * radius) continue;
                    const int nx = x + dx, ny = y + dy;
                    if (nx >= 0 && ny >= 0 && nx < width && ny < height) out[static_cast<std::size_t>(ny) * width + nx] = 1;
                }
            }
        }
    }
    blocked.swap(out);
}

} // namespace

Image collisionMapFromPieces(const std::vector<AcropolisPiece>& pieces, const GroundGrid& grid, float minY,
                             float maxY, float clearance) {
    const glm::vec2 cell = (grid.footprintMax - grid.footprintMin) / glm::vec2(grid.width, grid.height);
    std::vector<std::uint8_t> blocked(static_cast<std::size_t>(grid.width) * grid.height, 0);
    const float step = 0.3f * std::min(cell.x, cell.y);
    const auto mark = [&](const glm::vec3& p) {
        if (p.y < minY || p.y > maxY) return;
        const glm::vec2 t = (glm::vec2(p.x, p.z) - grid.footprintMin) / cell;
        const int x = static_cast<int>(std::floor(t.x)), y = static_cast<int>(std::floor(t.y));
        if (x >= 0 && y >= 0 && x < grid.width && y < grid.height) blocked[static_cast<std::size_t>(y) * grid.width + x] = 1;
    };
    for (const AcropolisPiece& piece : pieces) {
        if (piece.name == "floor" || piece.mesh == nullptr) continue;
        const Mesh& mesh = *piece.mesh;
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            glm::vec3 corner[3];
            for (int k = 0; k < 3; ++k)
                corner[k] = glm::vec3(piece.model * glm::vec4(mesh.vertices[mesh.indices[i + static_cast<std::size_t>(k)]].position, 1.0f));
            const float low = std::min({corner[0].y, corner[1].y, corner[2].y});
            const float high = std::max({corner[0].y, corner[1].y, corner[2].y});
            if (high < minY || low > maxY) continue;
            // Points over the triangle, closer together than a third of a texel.
            const float longest = std::max({glm::length(corner[1] - corner[0]), glm::length(corner[2] - corner[1]),
                                            glm::length(corner[0] - corner[2])});
            const int n = std::max(1, static_cast<int>(std::ceil(longest / step)));
            for (int a = 0; a <= n; ++a) {
                for (int b = 0; a + b <= n; ++b) {
                    const float u = static_cast<float>(a) / n, v = static_cast<float>(b) / n;
                    mark(corner[0] + u * (corner[1] - corner[0]) + v * (corner[2] - corner[0]));
                }
            }
        }
    }
    dilate(blocked, grid.width, grid.height, static_cast<int>(std::round(clearance / std::min(cell.x, cell.y))));
    Image image(grid.width, grid.height, 1);
    for (std::size_t i = 0; i < blocked.size(); ++i) image.data()[i] = blocked[i] ? 0 : 255;
    return image;
}

Image hillsHeightMap(int size, std::uint32_t seed) {
    HashRandom random(seed);
    struct Bump {
        float x, y, radius, height;
    };
    std::vector<Bump> bumps;
    for (int i = 0; i < 40; ++i) {
        Bump bump;
        bump.x = random.between(0.0f, 1.0f);
        bump.y = random.between(0.0f, 1.0f);
        bump.radius = random.between(0.1f, 0.3f);
        bump.height = random.between(-0.4f, 1.0f);
        bumps.push_back(bump);
    }
    // (1 - r^2 / R^2)^2 inside R: smooth, and the same bits on every machine (no libm).
    std::vector<float> values(static_cast<std::size_t>(size) * size, 0.0f);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = (x + 0.5f) / size, v = (y + 0.5f) / size;
            float h = 0.0f;
            for (const Bump& bump : bumps) {
                const float d2 = ((u - bump.x) * (u - bump.x) + (v - bump.y) * (v - bump.y)) / (bump.radius * bump.radius);
                if (d2 < 1.0f) h += bump.height * (1.0f - d2) * (1.0f - d2);
            }
            values[static_cast<std::size_t>(y) * size + x] = h;
        }
    }
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    const float lowest = *low, range = std::max(*high - *low, 1e-6f);
    Image image(size, size, 1);
    for (std::size_t i = 0; i < values.size(); ++i)
        image.data()[i] = static_cast<std::uint8_t>(std::lround((values[i] - lowest) / range * 255.0f));
    return image;
}

Image hillsCollisionMap(const Image& heights, const GroundGrid& grid, float heightRange, float waterLevel,
                        float maxSlope) {
    const int w = heights.width(), h = heights.height();
    const glm::vec2 cell = (grid.footprintMax - grid.footprintMin) / glm::vec2(w, h);
    Image image(w, h, 1);
    const auto at = [&](int x, int y) {
        x = std::clamp(x, 0, w - 1);
        y = std::clamp(y, 0, h - 1);
        return heights.data()[static_cast<std::size_t>(y) * w + x] / 255.0f;
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const float here = at(x, y);
            const float slopeX = std::fabs(at(x + 1, y) - at(x - 1, y)) * heightRange / (2.0f * cell.x);
            const float slopeZ = std::fabs(at(x, y + 1) - at(x, y - 1)) * heightRange / (2.0f * cell.y);
            const bool walkable = here >= waterLevel && std::max(slopeX, slopeZ) <= maxSlope;
            image.data()[static_cast<std::size_t>(y) * w + x] = walkable ? 255 : 0;
        }
    }
    return image;
}

std::vector<std::filesystem::path> writeExampleGroundMaps(const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    std::vector<std::filesystem::path> written;
    const GroundGrid acropolis{kAcropolisTexels, kAcropolisTexels, glm::vec2(-kAcropolisHalf), glm::vec2(kAcropolisHalf)};
    written.push_back(folder / "acropolis_collision.png");
    collisionMapFromPieces(acropolisPieces(), acropolis, 0.05f, 2.0f, 0.35f).savePng(written.back());
    const Image heights = hillsHeightMap(kHillsTexels, 11u);
    written.push_back(folder / "hills_height.png");
    heights.savePng(written.back());
    const GroundGrid hills{kHillsTexels, kHillsTexels, glm::vec2(-kHillsHalf), glm::vec2(kHillsHalf)};
    written.push_back(folder / "hills_collision.png");
    hillsCollisionMap(heights, hills, kHillsHeight, 0.07f, 0.6f).savePng(written.back());
    return written;
}

} // namespace stoa
