#include "Textures.hpp"

#include "Noise.hpp"
#include "PortableMath.hpp"

#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace stoa::assets {

namespace {

glm::u8vec4 toBytes(glm::vec3 colour, float alpha = 1.0f) {
    const glm::vec3 c = glm::clamp(colour, 0.0f, 1.0f) * 255.0f + 0.5f;
    return {static_cast<std::uint8_t>(c.r), static_cast<std::uint8_t>(c.g), static_cast<std::uint8_t>(c.b),
            static_cast<std::uint8_t>(std::clamp(alpha, 0.0f, 1.0f) * 255.0f + 0.5f)};
}

// Where a texel lies in a running-bond pattern of blocks (courses offset by
// half a block): which block, and how far (in texels) from its nearest joint.
struct BlockSample {
    int column = 0, row = 0;   // the block, wrapped to the repeat
    float edgeDistance = 0.0f; // texels to the nearest joint's centre line
};

BlockSample blockAt(float x, float y, float blockWidth, float blockHeight, int blocksPerRow) {
    BlockSample sample;
    sample.row = static_cast<int>(std::floor(y / blockHeight));
    const float shifted = x + (sample.row % 2 == 1 ? 0.5f * blockWidth : 0.0f);
    sample.column = static_cast<int>(std::floor(shifted / blockWidth)) % blocksPerRow;
    const float inX = shifted - std::floor(shifted / blockWidth) * blockWidth;
    const float inY = y - static_cast<float>(sample.row) * blockHeight;
    sample.edgeDistance = std::min({inX, blockWidth - inX, inY, blockHeight - inY});
    return sample;
}

// The shared layout of the wall's diffuse and height maps.
struct WallTexel {
    float height;       // 0..1
    float blockShade;   // per-block colour variation, 0..1
    float roughness;    // the surface noise, 0..1
    bool mortar;
};

WallTexel wallTexel(int x, int y, int size) {
    const float scale = static_cast<float>(size) / 256.0f;  // the layout is drawn for 256 texels
    const BlockSample block = blockAt(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, 64.0f * scale, 32.0f * scale, 4);
    const float roughness = tiledFbm(static_cast<float>(x) * 16.0f / size, static_cast<float>(y) * 16.0f / size, 16, 4, 7U);
    WallTexel texel;
    texel.roughness = roughness;
    texel.blockShade = hashToUnit(block.column, block.row, 0, 3U);
    const float mortarHalfWidth = 2.0f * scale, bevel = 5.0f * scale;
    texel.mortar = block.edgeDistance < mortarHalfWidth;
    if (texel.mortar) {
        texel.height = 0.08f + 0.06f * roughness;
    } else {
        // Rounded edges: the face rises from the joint over `bevel` texels (a quarter circle).
        const float t = std::min((block.edgeDistance - mortarHalfWidth) / bevel, 1.0f);
        const float rise = std::sqrt(1.0f - (1.0f - t) * (1.0f - t));
        texel.height = 0.25f + rise * (0.55f + 0.2f * roughness);
    }
    return texel;
}

} // namespace

Image floorDiffuse(int size) {
    Image image(size, size, 3);
    const float scale = static_cast<float>(size) / 512.0f;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // 2 slabs across and 4 courses down the 2 m repeat: 1 m x 0.5 m slabs.
            const BlockSample slab = blockAt(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, 256.0f * scale, 128.0f * scale, 2);
            const float u = static_cast<float>(x) * 8.0f / size, v = static_cast<float>(y) * 8.0f / size;
            const float grain = tiledFbm(u, v, 8, 5, 17U);
            const float tint = hashToUnit(slab.column, slab.row, 0, 5U);
            glm::vec3 stone = glm::mix(glm::vec3(0.66f, 0.62f, 0.55f), glm::vec3(0.78f, 0.74f, 0.66f), tint);
            stone *= 0.7f + 0.5f * grain;
            // Worn, darker edges and a dark joint.
            const float edge = glm::smoothstep(2.0f * scale, 10.0f * scale, slab.edgeDistance);
            const glm::vec3 joint(0.28f, 0.26f, 0.23f);
            image.setPixel(x, y, toBytes(glm::mix(joint, stone * (0.9f + 0.1f * edge), edge)));
        }
    return image;
}

namespace {

// 0 on clean marble, rising to 1 in the middle of a vein.
float marbleVein(int x, int y, int size) {
    const float u = static_cast<float>(x) / size, v = static_cast<float>(y) / size;
    const float turbulence = tiledFbm(u * 4.0f, v * 4.0f, 4, 5, 23U);
    // Diagonal bands (periodic in u and v, so the texture tiles) bent by turbulence.
    const auto band = static_cast<float>(portableSin(glm::two_pi<float>() * (u + 2.0f * v + 1.1f * turbulence)));
    const float closeness = 1.0f - std::abs(band), squared = closeness * closeness, fourth = squared * squared;
    return fourth * fourth * squared;  // closeness^10: a thin vein (PortableMath.hpp says why not std::pow)
}

} // namespace

Image columnDiffuse(int size) {
    Image image(size, size, 3);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float cloud = tiledFbm(static_cast<float>(x) * 8.0f / size, static_cast<float>(y) * 8.0f / size, 8, 4, 31U);
            const glm::vec3 marble = glm::vec3(0.93f, 0.91f, 0.87f) * (0.92f + 0.1f * cloud);
            image.setPixel(x, y, toBytes(glm::mix(marble, glm::vec3(0.50f, 0.53f, 0.58f), 0.7f * marbleVein(x, y, size))));
        }
    return image;
}

Image columnSpecular(int size) {
    Image image(size, size, 1);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float wear = tiledFbm(static_cast<float>(x) * 4.0f / size, static_cast<float>(y) * 4.0f / size, 4, 3, 37U);
            const float polish = 0.85f - 0.6f * marbleVein(x, y, size) - 0.35f * wear;
            image.setPixel(x, y, toBytes(glm::vec3(polish)));
        }
    return image;
}

Image wallDiffuse(int size) {
    Image image(size, size, 3);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const WallTexel texel = wallTexel(x, y, size);
            glm::vec3 colour;
            if (texel.mortar) {
                colour = glm::vec3(0.70f, 0.67f, 0.60f) * (0.9f + 0.15f * texel.roughness);
            } else {
                colour = glm::mix(glm::vec3(0.55f, 0.42f, 0.32f), glm::vec3(0.72f, 0.60f, 0.46f), texel.blockShade);
                // Lower parts of a block (recesses) a little darker, as dirt settles there.
                colour *= 0.75f + 0.3f * texel.height + 0.1f * texel.roughness;
            }
            image.setPixel(x, y, toBytes(colour));
        }
    return image;
}

Image wallHeight(int size) {
    Image image(size, size, 1);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) image.setPixel(x, y, toBytes(glm::vec3(wallTexel(x, y, size).height)));
    return image;
}

Image templeDiffuse(int size) {
    Image image(size, size, 4);
    const float scale = static_cast<float>(size) / 256.0f;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            // Courses of long blocks: 4 courses of 2 blocks per 3 m repeat.
            const BlockSample block = blockAt(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, 128.0f * scale, 64.0f * scale, 2);
            const float u = static_cast<float>(x) * 6.0f / size, v = static_cast<float>(y) * 6.0f / size;
            const float weathering = tiledFbm(u, v, 6, 5, 41U);
            const float streaks = tiledFbm(u * 4.0f, 0.5f, 24, 3, 43U);  // rain streaks: vary across, not down
            const float tint = hashToUnit(block.column, block.row, 0, 47U);
            glm::vec3 stone = glm::mix(glm::vec3(0.80f, 0.74f, 0.62f), glm::vec3(0.88f, 0.83f, 0.72f), tint);
            stone *= 0.8f + 0.25f * weathering - 0.12f * streaks;
            const float joint = glm::smoothstep(0.5f * scale, 2.5f * scale, block.edgeDistance);
            image.setPixel(x, y, toBytes(glm::mix(stone * 0.6f, stone, joint), 1.0f));
        }
    return image;
}

} // namespace stoa::assets
