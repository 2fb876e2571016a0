// deferred_benchmark [--width W] [--height H] [--lights N] [--runs R]: lab 08's
// scene on the headless context (llvmpipe) with the solutions' code, lit
// through stoa::DeferredRenderer three ways:
//   - forward: every fragment of every triangle loops over all the lights;
//   - light volumes: the G-buffer, the ambient pass, one sphere per light;
//   - tiled: the G-buffer, the ambient pass, the lights sorted into 16-pixel
//     tiles on the CPU (each tile bounded by the depths its pixels see, read
//     back from the G-buffer), one full-screen pass; the same with 8-pixel tiles;
// and the geometry pass alone (the G-buffer), for scale. The scene is lab 08's
// app's: acropolisPieces() and six more statues on pedestals along the path
// (acropolisAvenuePieces()), under N wandering lights
// (default 256, seed 1, at 0 s), seen by the graded cases' orbit camera, at WxH
// (default 1280x720). Each frame ends with glFinish(); after a warm-up frame of
// each, the four take turns for R rounds (default 5) and the median is
// printed, in wall and process CPU milliseconds (all threads), with the
// speed-up of volumes and tiles over forward and the G-buffer's memory. The
// three pictures are compared after the warm-up (the same light, three ways).
// $STOA_PREVIEW_DIR: the pictures are saved there. $STOA_HEADLESS picks the
// backend, $LP_NUM_THREADS llvmpipe's threads.

#include "BenchmarkTiming.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/TextureCache.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/image/ImageCompare.hpp>
#include <stoa/lab/Lab.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/DrawList.hpp>
#include <stoa/scene/PieceDrawList.hpp>
#include <stoa/scene/WanderingLights.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using stoa::benchmark::Clock;
using stoa::benchmark::median;
using stoa::benchmark::milliseconds;

double processSeconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);   // all threads: llvmpipe rasterizes on several
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

// One thing to time: its wall and CPU milliseconds, one per round.
struct Measured {
    const char* name;
    std::function<void()> frame;
    std::vector<double> wall, cpu;
};

void measureOnce(Measured& m) {
    glFinish();
    const double cpuStart = processSeconds();
    const Clock::time_point start = Clock::now();
    m.frame();
    glFinish();
    m.wall.push_back(milliseconds(start, Clock::now()));
    m.cpu.push_back((processSeconds() - cpuStart) * 1000.0);
}

struct Options {
    int width = 1280, height = 720, lights = 256, runs = 5;
};

bool parse(int argc, char** argv, Options& options) {
    for (int i = 1; i < argc; ++i) {
        int* value = nullptr;
        int low = 1, high = 1 << 14;
        if (std::strcmp(argv[i], "--width") == 0) value = &options.width;
        else if (std::strcmp(argv[i], "--height") == 0) value = &options.height;
        else if (std::strcmp(argv[i], "--lights") == 0) value = &options.lights, low = 0, high = 1 << 16;
        else if (std::strcmp(argv[i], "--runs") == 0) value = &options.runs, high = 1000;
        if (!value || i + 1 >= argc) return false;
        *value = std::atoi(argv[++i]);
        if (*value < low || *value > high) return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv) {
    Options options;
    if (!parse(argc, argv, options)) {
        std::fprintf(stderr, "usage: deferred_benchmark [--width W] [--height H] [--lights N] [--runs R]\n"
                             "  defaults: 1280x720, 256 lights, 5 runs\n");
        return 2;
    }
    std::printf("deferred_benchmark");
    for (int i = 1; i < argc; ++i) std::printf(" %s", argv[i]);
    std::printf("\n");
    try {
        stoa::HeadlessContext context;
        std::printf("%s\n", context.description().c_str());

        // The programs as lab 08's app loads them, the solution's g_buffer.glsl first on the path.
        stoa::LabResources resources({STOA_SOLUTIONS_DIR, stoa::paths::shadersDir()});
        const auto load = [&](const std::string& vertex, const std::string& fragment) -> const stoa::Program& {
            return resources.loadProgram(vertex, fragment);
        };
        const stoa::DeferredPrograms programs = stoa::DeferredPrograms::load(load);
        stoa::DeferredRenderer renderer(programs);

        const stoa::PieceDrawList scene(stoa::acropolisAvenuePieces());
        stoa::WanderingLightsOptions lightOptions;
        lightOptions.count = options.lights;
        const std::vector<stoa::PointLight> lights = stoa::wanderingLights(lightOptions, 0.0f);
        const stoa::SceneLighting lighting;
        const stoa::OrbitCamera camera({0.0f, 1.5f, 0.0f}, 20.0f, 20.0f, 20.0f);   // cases.ini's volumes_256_lights
        const glm::ivec2 size(options.width, options.height);

        const stoa::Framebuffer target(size.x, size.y);
        target.bind();
        std::printf("scene: %zu triangles in %zu draws, %d lights, %dx%d, median of %d interleaved rounds\n",
                    scene.triangleCount(), scene.items().size(), options.lights, size.x, size.y, options.runs);

        const auto frame = [&](stoa::LightingMode mode, int tileSize = 16) {
            return [&, mode, tileSize] {
                stoa::DeferredSettings settings;
                settings.mode = mode;
                settings.tileSize = tileSize;
                renderer.render(scene.items(), lights, lighting, camera, size, settings);
            };
        };
        std::vector<Measured> measurements{
            {"forward", frame(stoa::LightingMode::Forward), {}, {}},
            {"light volumes", frame(stoa::LightingMode::Volumes), {}, {}},
            {"tiled (16 px)", frame(stoa::LightingMode::Tiled), {}, {}},
            {"tiled (8 px)", frame(stoa::LightingMode::Tiled, 8), {}, {}},
            {"geometry pass alone",
             [&] {
                 renderer.renderGeometry(scene.items(), camera, size);
                 target.bind();   // renderGeometry() leaves the G-buffer bound
             },
             {}, {}},
        };

        // Warm-up: programs' first draws, the targets allocated; the pictures kept.
        std::vector<stoa::Image> pictures;
        stoa::DeferredStats volumeStats, tileStats;
        int tileCount = 0;
        for (std::size_t i = 0; i < measurements.size(); ++i) {
            measurements[i].frame();
            glFinish();
            if (i < 3) pictures.push_back(target.readColor());
            if (i == 1) volumeStats = renderer.stats();
            if (i == 2) {
                tileStats = renderer.stats();
                tileCount = renderer.tileLists().grid.tileCount();
            }
        }
        const std::size_t gBufferBytes = renderer.gBuffer().bytes();

        for (int round = 0; round < options.runs; ++round)
            for (Measured& m : measurements) measureOnce(m);

        std::printf("  %-22s %10s %10s\n", "", "wall ms", "CPU ms");
        for (const Measured& m : measurements)
            std::printf("  %-22s %10.1f %10.1f\n", m.name, median(m.wall), median(m.cpu));
        const double forward = median(measurements[0].wall), forwardCpu = median(measurements[0].cpu);
        std::printf("  speed-up over forward: light volumes %.2fx (CPU %.2fx), tiled %.2fx (CPU %.2fx), "
                    "tiled 8 px %.2fx (CPU %.2fx)\n",
                    forward / median(measurements[1].wall), forwardCpu / median(measurements[1].cpu),
                    forward / median(measurements[2].wall), forwardCpu / median(measurements[2].cpu),
                    forward / median(measurements[3].wall), forwardCpu / median(measurements[3].cpu));
        std::printf("  light volumes drawn: %d of %d; tile lists: %ld entries over %d tiles (%.1f lights per tile)\n",
                    volumeStats.lightsDrawn, volumeStats.lights, tileStats.tileListEntries, tileCount,
                    static_cast<double>(tileStats.tileListEntries) / tileCount);
        std::printf("  G-buffer at %dx%d: %.2f MiB (%zu bytes, %.0f per pixel)\n", size.x, size.y,
                    static_cast<double>(gBufferBytes) / (1024.0 * 1024.0), gBufferBytes,
                    static_cast<double>(gBufferBytes) / (static_cast<double>(size.x) * size.y));

        const stoa::CompareResult volumesForward = stoa::compareImages(pictures[1], pictures[0]);
        const stoa::CompareResult tiledVolumes = stoa::compareImages(pictures[2], pictures[1]);
        std::printf("  pictures: volumes vs forward %s (%s)\n", volumesForward.passed ? "the same" : "DIFFERENT",
                    volumesForward.summary.c_str());
        std::printf("            tiled vs volumes  %s (%s)\n", tiledVolumes.passed ? "the same" : "DIFFERENT",
                    tiledVolumes.summary.c_str());
        if (const char* folder = std::getenv("STOA_PREVIEW_DIR")) {
            const char* names[] = {"deferred_forward.png", "deferred_volumes.png", "deferred_tiled.png"};
            for (int i = 0; i < 3; ++i) pictures[i].savePng(std::filesystem::path(folder) / names[i]);
        }
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "deferred_benchmark: %s\n", error.what());
        return 1;
    }
}
