// shadow_benchmark [RUNS]: lab 05's shadow maps on the headless context
// (llvmpipe) at 1280x720 with the Acropolis scene and the solutions' code, the
// median of RUNS rounds (default 9, after a warm-up round; the measurements
// take turns within a round):
//   - the shadow pass alone (a 2048^2 depth map from the sun),
//   - the whole frame (shadow pass + lit pass) with a single tap, 2x2 and 3x3 PCF,
//   - the whole frame without shadows, for scale,
//   - the whole frame with 3 and 4 cascades of 1024^2 (as many texels as the
//     one 2048^2 map for 4), single tap,
// and the ratio of the 3x3 frame to the single-tap one (target: within 2x).
// Each measurement ends with glFinish(), so it is the time llvmpipe takes to
// draw; wall time and the process's CPU time (all threads) are both printed, and
// the ratio uses CPU time, which a busy machine disturbs less.
// The number of llvmpipe threads follows $LP_NUM_THREADS (Mesa's default: one per core).

#include "BenchmarkTiming.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include "lab05.hpp"
#include <stoa/render/ShadowRenderer.hpp>
#include <stoa/scene/AcropolisScene.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <functional>
#include <vector>

namespace {

using stoa::benchmark::median;
using stoa::benchmark::milliseconds;

constexpr int kWidth = 1280;
constexpr int kHeight = 720;
constexpr int kMapSize = 2048;
constexpr int kCascadeMapSize = 1024;

double processSeconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);   // all threads: llvmpipe rasterizes on several
    return now.tv_sec + now.tv_nsec * 1e-9;
}

// One thing to time: its wall and CPU milliseconds, one per round.
struct Measured {
    const char* name;
    std::function<void()> work;
    std::vector<double> wall, cpu;
};

// Runs every measurement once per round, `runs` rounds, interleaved so that a
// change in the machine's load hits all of them alike. Each ends with glFinish().
void measure(std::vector<Measured>& measurements, int runs) {
    for (Measured& m : measurements) {   // warm-up: shader variants compiled, the map allocated
        m.work();
        glFinish();
    }
    for (int round = 0; round < runs; ++round)
        for (Measured& m : measurements) {
            glFinish();
            const double cpuStart = processSeconds();
            const auto start = std::chrono::steady_clock::now();
            m.work();
            glFinish();
            m.wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            m.cpu.push_back((processSeconds() - cpuStart) * 1000.0);
        }
}

} // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
    try {
        stoa::HeadlessContext context;
        const std::vector<std::filesystem::path> searchPath{STOA_SOLUTIONS_DIR, stoa::paths::shadersDir()};
        const stoa::Program depth = stoa::Program::fromFiles("shadows/depth.vert", "shadows/depth.frag", searchPath);
        const stoa::Program shadowed =
            stoa::Program::fromFiles("shadows/shadowed.vert", "shadows/shadowed.frag", searchPath);
        const stoa::Program mapView =
            stoa::Program::fromFiles("shadows/depth_view.vert", "shadows/depth_view.frag", searchPath);
        const stoa::Program cascaded =
            stoa::Program::fromFiles("shadows/shadowed.vert", "shadows/cascaded.frag", searchPath);
        stoa::ShadowRenderer renderer(depth, shadowed, mapView);
        renderer.setCascadeProgram(&cascaded);

        stoa::Scene scene;
        stoa::buildAcropolisScene(scene);   // with acropolisSun()
        const auto [low, high] = stoa::acropolisBounds();
        stoa::ShadowLight light;
        light.lightSpaceMatrix = stoa::directionalLightMatrix(scene.directionalLights.at(0).direction, low, high);
        light.sceneMin = low;
        light.sceneMax = high;
        const stoa::OrbitCamera camera({0.0f, 2.0f, -3.0f}, 24.0f, 20.0f, 22.0f);

        stoa::Framebuffer target(kWidth, kHeight);
        target.bind();
        stoa::ShadowSettings settings;
        settings.mapSize = kMapSize;
        const glm::ivec2 size(kWidth, kHeight);

        std::printf("shadow_benchmark: %s\n", context.description().c_str());
        std::printf("Acropolis, %dx%d, shadow map %d^2, median of %d interleaved rounds\n", kWidth, kHeight, kMapSize,
                    runs);
        const auto frame = [&](bool enabled, stoa::PcfMode pcf) {
            return [&, enabled, pcf] {
                stoa::ShadowSettings frameSettings = settings;
                frameSettings.enabled = enabled;
                frameSettings.pcf = pcf;
                renderer.render(scene, camera, size, light, frameSettings);
            };
        };
        const auto cascadedFrame = [&](int count) {
            return [&, count] {
                stoa::ShadowSettings frameSettings = settings;
                frameSettings.mapSize = kCascadeMapSize;
                frameSettings.cascades.count = count;
                renderer.render(scene, camera, size, light, frameSettings);
            };
        };
        std::vector<Measured> measurements{
            {"shadow pass alone", [&] { renderer.renderShadowMap(scene, light, kMapSize); }, {}, {}},
            {"frame, no shadows", frame(false, stoa::PcfMode::Single), {}, {}},
            {"frame, single tap", frame(true, stoa::PcfMode::Single), {}, {}},
            {"frame, 2x2 PCF", frame(true, stoa::PcfMode::TwoByTwo), {}, {}},
            {"frame, 3x3 PCF", frame(true, stoa::PcfMode::ThreeByThree), {}, {}},
            {"frame, 3 cascades", cascadedFrame(3), {}, {}},
            {"frame, 4 cascades", cascadedFrame(4), {}, {}},
        };
        measure(measurements, runs);
        std::printf("  %-20s %10s %10s\n", "", "wall ms", "CPU ms");
        for (const Measured& m : measurements)
            std::printf("  %-20s %10.2f %10.2f\n", m.name, median(m.wall), median(m.cpu));
        const double pass = median(measurements[0].cpu);
        const double single = median(measurements[2].cpu), threeByThree = median(measurements[4].cpu);
        std::printf("  3x3 / single-tap frame (CPU)      %6.2f   (target: <= 2)\n", threeByThree / single);
        std::printf("  3x3 / single-tap lit pass (CPU)   %6.2f   (the frame less the shadow pass)\n",
                    (threeByThree - pass) / (single - pass));
        std::printf("  4 cascades / single-map frame (CPU) %4.2f   (4 x %d^2 against 1 x %d^2, single tap)\n",
                    median(measurements[6].cpu) / single, kCascadeMapSize, kMapSize);
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "shadow_benchmark: %s\n", error.what());
        return 1;
    }
}
