// light_assignment_benchmark [--runs R]: the tiled pass's light assignment
// alone, on the CPU, for the showcase's 302 point lights (assets/scenes/
// showcase.json: its two lamps and its swarm of 300 at 1 s) seen by its orbit
// camera (far 400 m, as showcase_benchmark), at 1280x720 and 1920x1080 with
// 16-pixel tiles, side by side in one run, medians of R runs (default 15):
//   - lab 08's reference buildTileLightLists() (the solutions' tiled_lights.cpp,
//     what the lab's own program calls) against the framework's
//     TileLightBinner::assign() (what the editor and the showcase call); both
//     on this thread only, one core; their lists are compared entry for entry;
//   - the tiles' depth ranges from the depth buffer: the per-pixel conversion
//     the renderer made before against the per-tile extremes it makes now;
//   - the depth buffer's readback itself (glReadPixels of GL_DEPTH24_STENCIL8
//     as floats, as the renderer reads it, and for scale as packed depth and
//     stencil; on the headless context: llvmpipe unless $STOA_HEADLESS says).
// The depths are those of the ground (y = 0) under the camera, sky above the
// horizon, in 24-bit steps as the G-buffer holds them; the columns and statues
// are left out (fewer surfaces in front of the lights: a few more entries).

#include "BenchmarkTiming.hpp"
#include "TileDepthRanges.hpp"
#include "TileLightBinner.hpp"
#include "lab08.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/editor/EditorSceneFile.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/render/DeferredShading.hpp>
#include <stoa/scene/WanderingLights.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <vector>

using namespace stoa;
using namespace stoa::benchmark;

namespace {

constexpr float kCutoff = 1.0f / 64.0f;   // DeferredSettings' default
constexpr int kTileSize = 16;

// The showcase's lights as the editor lights them: its lamps, then its swarm.
std::vector<PointLight> showcaseLights(const EditorScene& scene, float seconds) {
    std::vector<PointLight> lights;
    for (const EditorLight& lamp : scene.lights) {
        if (!lamp.on) continue;
        PointLight light;
        light.position = lamp.position;
        light.color = lamp.color;
        light.attenuation = glm::vec3(1.0f, 4.5f / lamp.radius, 75.0f / (lamp.radius * lamp.radius));
        lights.push_back(light);
    }
    WanderingLightsOptions options;
    options.count = scene.lightSwarm.count;
    options.seed = static_cast<std::uint32_t>(scene.lightSwarm.seed);
    options.regionMin = {-scene.lightSwarm.radius, 0.3f, -scene.lightSwarm.radius};
    options.regionMax = {scene.lightSwarm.radius, scene.lightSwarm.height, scene.lightSwarm.radius};
    options.brightness = scene.lightSwarm.brightness;
    const std::vector<PointLight> swarm = wanderingLights(options, seconds);
    lights.insert(lights.end(), swarm.begin(), swarm.end());
    return lights;
}

// The window depth of the ground (y = 0) through each pixel's centre, 1 where
// the ray misses it or meets it past the far plane; rows from the bottom.
std::vector<float> groundDepth(const glm::mat4& view, const glm::mat4& projection, glm::ivec2 size) {
    const glm::mat4 inverse = glm::inverse(projection * view);
    const glm::mat4 viewProjection = projection * view;
    std::vector<float> depth(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y), 1.0f);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const glm::vec2 ndc((x + 0.5f) / size.x * 2.0f - 1.0f, (y + 0.5f) / size.y * 2.0f - 1.0f);
            const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
            const glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
            const glm::vec3 a = glm::vec3(nearPoint) / nearPoint.w, b = glm::vec3(farPoint) / farPoint.w;
            if ((a.y > 0.0f) == (b.y > 0.0f)) continue;   // the ground is not between the planes
            const glm::vec3 hit = a + (b - a) * (a.y / (a.y - b.y));
            const glm::vec4 clip = viewProjection * glm::vec4(hit, 1.0f);
            const double window = std::clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
            const std::uint32_t steps = static_cast<std::uint32_t>(window * 16777215.0);   // 24 bits
            depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x)] =
                static_cast<float>(steps / 16777215.0);
        }
    return depth;
}

// The renderer's tile depths before TileLightBinner: every pixel converted.
std::vector<DepthRange> perPixelDepthRanges(const std::vector<float>& depth, glm::ivec2 size, const glm::mat4& projection,
                                            const TileGrid& grid) {
    const float a = projection[2][2], b = projection[3][2];
    std::vector<DepthRange> ranges(static_cast<std::size_t>(grid.tileCount()));
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const float d = depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + static_cast<std::size_t>(x)];
            if (d >= 1.0f) continue;
            const float distance = b / (2.0f * d - 1.0f + a);
            DepthRange& range = ranges[static_cast<std::size_t>(grid.index({x / grid.tileSize, y / grid.tileSize}))];
            if (range.empty()) {
                range.nearest = range.farthest = distance;
            } else {
                range.nearest = std::min(range.nearest, distance);
                range.farthest = std::max(range.farthest, distance);
            }
        }
    return ranges;
}

template <typename Work> double timed(Work&& work) {
    const Clock::time_point start = Clock::now();
    work();
    return milliseconds(start, Clock::now());
}

// One picture size: the figures, side by side. False when the lists differ.
bool measure(const EditorScene& scene, glm::ivec2 size, int runs) {
    OrbitCamera camera(scene.camera.target, scene.camera.distance, scene.camera.yawDegrees, scene.camera.pitchDegrees);
    camera.setProjection(camera.fovYDegrees(), camera.nearPlane(), 400.0f);
    const glm::mat4 view = camera.viewMatrix();
    const glm::mat4 projection = camera.projectionMatrix(static_cast<float>(size.x) / static_cast<float>(size.y));
    std::vector<LightSphere> spheres;
    for (const PointLight& light : showcaseLights(scene, 1.0f))
        spheres.push_back({glm::vec3(view * glm::vec4(light.position, 1.0f)), lightReach(light, kCutoff)});
    TileGrid grid;
    grid.viewport = size;
    grid.tileSize = kTileSize;
    const std::vector<float> depth = groundDepth(view, projection, size);

    // The readback, on the headless context.
    FramebufferOptions options;
    options.color = false;
    options.depthStencilTexture = true;
    const Framebuffer target(size.x, size.y, options);
    target.bind();
    glClearDepth(0.5);
    glClear(GL_DEPTH_BUFFER_BIT);
    std::vector<float> readBack(depth.size());
    std::vector<std::uint32_t> readBackPacked(depth.size());

    TileLightBinner binner;
    stoa::TileDepthRanges tileDepths;
    TileLightLists fast, reference;
    std::vector<double> readTimes, packedTimes, pixelTimes, tileTimes, referenceTimes, fastTimes;
    bool same = true;
    for (int run = -1; run < runs; ++run) {   // run -1: warm-up, not counted
        const double read = timed([&] { target.readPixels(-1, 0, 0, size.x, size.y, GL_DEPTH_COMPONENT, GL_FLOAT, readBack.data()); });
        const double packed = timed([&] {
            target.readPixels(-1, 0, 0, size.x, size.y, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, readBackPacked.data());
        });
        std::vector<DepthRange> before;
        const double pixel = timed([&] { before = perPixelDepthRanges(depth, size, projection, grid); });
        const double tile = timed([&] { tileDepths.compute(depth.data(), size, projection, grid); });
        const std::vector<DepthRange>& depths = tileDepths.compute(depth.data(), size, projection, grid);
        const double slow = timed([&] { reference = buildTileLightLists(spheres, projection, camera.nearPlane(), grid, depths); });
        const double quick = timed([&] { binner.assign(spheres, projection, camera.nearPlane(), grid, depths, fast); });
        same = same && fast.offsets == reference.offsets && fast.lights == reference.lights;
        for (std::size_t t = 0; t < before.size(); ++t)
            same = same && std::memcmp(&before[t], &depths[t], sizeof(DepthRange)) == 0;
        if (run < 0) continue;
        readTimes.push_back(read);
        packedTimes.push_back(packed);
        pixelTimes.push_back(pixel);
        tileTimes.push_back(tile);
        referenceTimes.push_back(slow);
        fastTimes.push_back(quick);
    }
    std::printf("%dx%d, %d tiles of %d px, %zu lights, %zu tile-list entries:\n", size.x, size.y, grid.tileCount(),
                kTileSize, spheres.size(), reference.lights.size());
    const double slow = median(referenceTimes), quick = median(fastTimes);
    std::printf("  assignment, lab 08's buildTileLightLists (solution)  %7.3f ms\n", slow);
    std::printf("  assignment, framework TileLightBinner::assign        %7.3f ms   (%.1fx)\n", quick, slow / quick);
    std::printf("  tile depth ranges, every pixel converted (before)    %7.3f ms\n", median(pixelTimes));
    std::printf("  tile depth ranges, each tile's extremes (now)        %7.3f ms\n", median(tileTimes));
    std::printf("  depth readback, glReadPixels as floats               %7.3f ms\n", median(readTimes));
    std::printf("  depth readback, as 24-bit depth and stencil (for scale) %4.3f ms\n", median(packedTimes));
    std::printf("  same lists and depth ranges: %s\n", same ? "yes" : "NO");
    return same;
}

} // namespace

int main(int argc, char** argv) {
    int runs = 15;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = std::max(1, std::atoi(argv[++i]));
        } else {
            std::fprintf(stderr, "usage: light_assignment_benchmark [--runs R]\n");
            return 2;
        }
    }
    try {
        const EditorScene scene = loadEditorScene(paths::assetsDir() / "scenes" / "showcase.json");
        HeadlessContext context;
        std::printf("light assignment (one thread), the showcase's lights and camera, medians of %d runs, %s:\n", runs,
                    context.description().c_str());
        bool same = true;
        for (const glm::ivec2 size : {glm::ivec2(1280, 720), glm::ivec2(1920, 1080)}) same = measure(scene, size, runs) && same;
        return same ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "light_assignment_benchmark: %s\n", error.what());
        return 1;
    }
}
