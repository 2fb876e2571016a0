// ssao_benchmark [--width W] [--height H] [--runs N]: lab 09's screen-space
// ambient occlusion with the solutions' code (kernel.cpp, ssao.glsl and lab 08's
// g_buffer.glsl), on the headless context (llvmpipe) at 1280x720 by default.
// The frame is drawn as labs/09_ssao/lab.cpp draws its "final" view: lab 08's
// G-buffer of the Acropolis (acropolisPieces()) through
// DeferredRenderer::renderGeometry(), the occlusion pass (shaders/ssao/ssao.frag)
// into an R8 target, the blur pass (shaders/ssao/blur.frag) into another, then
// DeferredRenderer::render() reusing the G-buffer, its ambient light times the
// blurred occlusion; the lab's lighting, radius 1 m, bias 0.025 m, kernel seed 1,
// noise seed 2, no point lights, the camera of the case column_bases_raw.
// For kernels of 16, 32 and 64 samples, and the frame without occlusion for
// scale, the median of N rounds (default 7, after a warm-up round; the kernel
// sizes take turns within a round) of:
//   - a frame with glFinish() after each pass: the geometry, occlusion, blur
//     and lighting passes' times,
//   - the same frame with one glFinish() at its end: the frame time,
// and the occlusion + blur passes' share of the frame: the median over the
// rounds of their time over the sum of the four passes of the same frame (a
// ratio within one frame, which a change in the machine's load disturbs less
// than a ratio of two medians). The mean of the blurred occlusion is printed as
// a check that the passes drew something.
// $STOA_PREVIEW_DIR: the 32-sample frame and its blurred occlusion are saved there.
// $STOA_HEADLESS picks the backend, $LP_NUM_THREADS llvmpipe's threads.

#include "BenchmarkTiming.hpp"
#include "lab09.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/lab/Lab.hpp>
#include <stoa/render/AmbientOcclusion.hpp>
#include <stoa/render/AmbientOcclusionPass.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/PieceDrawList.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using stoa::benchmark::Clock;
using stoa::benchmark::median;
using stoa::benchmark::milliseconds;

const std::vector<int> kKernelSizes{16, 32, 64};
constexpr float kRadius = 1.0f;         // the lab's defaults
constexpr float kBias = 0.025f;
constexpr std::uint32_t kKernelSeed = 1;
constexpr std::uint32_t kNoiseSeed = 2;

// Lab 09's passes as its app draws them (stoa::AmbientOcclusionPass, with
// the solution's kernel and noise), for one kernel size.
class OcclusionFrame {
public:
    OcclusionFrame(const stoa::Program& occlusion, const stoa::Program& blur, const stoa::DeferredRenderer& renderer,
                   int kernelSize, glm::ivec2 size)
        : m_pass(occlusion, blur), m_renderer(renderer), m_size(size) {
        m_pass.setKernel(stoa::ssaoKernel(kernelSize, kKernelSeed), stoa::ssaoNoise(kNoiseSeed));
    }

    void occlusionPass() { m_pass.occlusion(m_renderer, m_size, {kRadius, kBias}); }
    void blurPass() { m_pass.blur(); }
    const stoa::Texture2D* blurred() const { return &m_pass.blurred(); }

    /// The blurred occlusion, one byte per pixel (0 hidden .. 255 open), rows bottom-up.
    std::vector<unsigned char> readBlurred() const {
        std::vector<unsigned char> values(static_cast<std::size_t>(m_size.x) * m_size.y);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        m_pass.blurredTarget().readPixels(0, 0, 0, m_size.x, m_size.y, GL_RED, GL_UNSIGNED_BYTE, values.data());
        return values;
    }

    /// The mean of the blurred occlusion, 0 (hidden) .. 1 (open).
    double meanOcclusion() const {
        const std::vector<unsigned char> values = readBlurred();
        double sum = 0.0;
        for (unsigned char v : values) sum += v;
        return sum / (255.0 * static_cast<double>(values.size()));
    }

    /// The blurred occlusion as a grey picture, top row first.
    stoa::Image blurredImage() const {
        const std::vector<unsigned char> values = readBlurred();
        stoa::Image image(m_size.x, m_size.y, 1);
        for (int y = 0; y < m_size.y; ++y)
            std::copy_n(values.data() + static_cast<std::size_t>(m_size.y - 1 - y) * m_size.x, m_size.x,
                        image.data() + static_cast<std::size_t>(y) * m_size.x);
        return image;
    }

private:
    stoa::AmbientOcclusionPass m_pass;
    const stoa::DeferredRenderer& m_renderer;
    glm::ivec2 m_size;
};

// One row of the table: a kernel size, or 0 for the frame without occlusion.
struct Row {
    int kernelSize = 0;
    std::unique_ptr<OcclusionFrame> frame;
    std::vector<double> geometry, occlusion, blur, lighting, whole;

    /// Per round: (occlusion + blur) / (the four passes), in %.
    std::vector<double> shares() const {
        std::vector<double> result;
        for (std::size_t k = 0; k < occlusion.size(); ++k)
            result.push_back(100.0 * (occlusion[k] + blur[k]) / (geometry[k] + occlusion[k] + blur[k] + lighting[k]));
        return result;
    }
};

int parsePositive(const char* text, const char* option) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < 1 || value > 16384)
        throw std::runtime_error(std::string("ssao_benchmark: ") + option + " needs a positive integer, not '" + text +
                                 "'");
    return static_cast<int>(value);
}

} // namespace

int main(int argc, char** argv) {
    int width = 1280, height = 720, runs = 7;
    try {
        for (int i = 1; i < argc; ++i) {
            const bool hasValue = i + 1 < argc;
            if (std::strcmp(argv[i], "--width") == 0 && hasValue) width = parsePositive(argv[++i], "--width");
            else if (std::strcmp(argv[i], "--height") == 0 && hasValue) height = parsePositive(argv[++i], "--height");
            else if (std::strcmp(argv[i], "--runs") == 0 && hasValue) runs = parsePositive(argv[++i], "--runs");
            else {
                std::fprintf(stderr, "usage: ssao_benchmark [--width W] [--height H] [--runs N]\n");
                return 2;
            }
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s\nusage: ssao_benchmark [--width W] [--height H] [--runs N]\n", error.what());
        return 2;
    }
    std::printf("ssao_benchmark");
    for (int i = 1; i < argc; ++i) std::printf(" %s", argv[i]);
    std::printf("\n");
    try {
        stoa::HeadlessContext context;
        std::printf("%s\n", context.description().c_str());

        // The search path of lab 09's program in a solutions build
        // (framework/cmake/StoaLab.cmake): 08_deferred/student/g_buffer.glsl and
        // 09_ssao/student/ssao.glsl from solutions/, then shaders/.
        const std::filesystem::path solutions = STOA_SOLUTIONS_DIR;
        const std::vector<std::filesystem::path> searchPath{solutions, stoa::paths::shadersDir()};
        stoa::LabResources resources(searchPath);
        const auto load = [&](const std::string& vertex, const std::string& fragment) -> const stoa::Program& {
            return resources.loadProgram(vertex, fragment);
        };
        const stoa::DeferredPrograms programs = stoa::DeferredPrograms::load(load);
        const stoa::Program& occlusion = load("basic/image.vert", "ssao/ssao.frag");
        const stoa::Program& blur = load("basic/image.vert", "ssao/blur.frag");
        stoa::DeferredRenderer renderer(programs);
        const stoa::PieceDrawList scene(stoa::acropolisPieces());

        stoa::SceneLighting lighting;   // as the lab
        lighting.ambient = glm::vec3(0.62f, 0.64f, 0.68f);
        lighting.moon = stoa::acropolisSun();
        lighting.moon.color *= 0.45f;
        lighting.sky = glm::vec3(0.55f, 0.68f, 0.85f);
        const std::vector<stoa::PointLight> lights;
        // The camera of the case column_bases_raw (labs/09_ssao/cases.ini).
        stoa::OrbitCamera camera(glm::vec3(-1.0f, 0.8f, -3.0f), 7.0f, 25.0f, 15.0f);

        const glm::ivec2 size(width, height);
        const stoa::Framebuffer target(width, height);
        target.bind();
        const GLuint output = stoa::StateCache::current().drawFramebuffer();

        std::vector<Row> rows(kKernelSizes.size() + 1);
        for (std::size_t i = 0; i < kKernelSizes.size(); ++i) {
            rows[i].kernelSize = kKernelSizes[i];
            rows[i].frame = std::make_unique<OcclusionFrame>(occlusion, blur, renderer, kKernelSizes[i], size);
        }

        // One frame; with `split`, glFinish() after each pass and its time kept.
        const auto drawFrame = [&](Row& row, bool split) {
            const auto finish = [&](std::vector<double>& into, Clock::time_point& from) {
                if (!split) return;
                glFinish();
                const Clock::time_point now = Clock::now();
                into.push_back(milliseconds(from, now));
                from = now;
            };
            glFinish();
            const Clock::time_point start = Clock::now();
            Clock::time_point from = start;
            renderer.renderGeometry(scene.items(), camera, size);
            finish(row.geometry, from);
            if (row.frame) {
                row.frame->occlusionPass();
                finish(row.occlusion, from);
                row.frame->blurPass();
                finish(row.blur, from);
            }
            stoa::StateCache::current().bindFramebuffer(output);
            stoa::DeferredSettings settings;
            settings.reuseGBuffer = true;
            settings.ambientOcclusion = row.frame ? row.frame->blurred() : nullptr;
            renderer.render(scene.items(), lights, lighting, camera, size, settings);
            finish(row.lighting, from);
            glFinish();
            if (!split) row.whole.push_back(milliseconds(start, Clock::now()));
        };

        // Warm-up: every program's first draw (llvmpipe compiles its shader
        // variants then), the pictures and the check.
        std::vector<double> meanOcclusion(rows.size(), 1.0);
        for (std::size_t i = 0; i < rows.size(); ++i) {
            drawFrame(rows[i], true);
            drawFrame(rows[i], false);
            if (rows[i].frame) meanOcclusion[i] = rows[i].frame->meanOcclusion();
            if (const char* folder = std::getenv("STOA_PREVIEW_DIR"); folder && rows[i].kernelSize == 32) {
                target.readColor().savePng(std::filesystem::path(folder) / "ssao_frame_32.png");
                rows[i].frame->blurredImage().savePng(std::filesystem::path(folder) / "ssao_blurred_32.png");
            }
            rows[i].geometry.clear();
            rows[i].occlusion.clear();
            rows[i].blur.clear();
            rows[i].lighting.clear();
            rows[i].whole.clear();
        }
        for (int round = 0; round < runs; ++round)
            for (Row& row : rows) {
                drawFrame(row, true);
                drawFrame(row, false);
            }

        std::printf("Acropolis (%zu triangles), %dx%d, radius %.2f m, bias %.3f m, median of %d interleaved rounds\n",
                    scene.triangleCount(), width, height, kRadius, kBias, runs);
        std::printf("(passes: a frame with glFinish() after each; frame: the same frame with one glFinish() at its end;\n"
                    " ao share: occlusion + blur over that frame's four passes, the median of the rounds' ratios)\n");
        std::printf("  %-8s %12s %13s %8s %12s %9s %11s %9s\n", "kernel", "geometry ms", "occlusion ms", "blur ms",
                    "lighting ms", "frame ms", "ao share %", "mean AO");
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const Row& row = rows[i];
            const double frame = median(row.whole);
            if (row.frame) {
                std::printf("  %-8d %12.2f %13.2f %8.2f %12.2f %9.2f %11.1f %9.3f\n", row.kernelSize,
                            median(row.geometry), median(row.occlusion), median(row.blur), median(row.lighting), frame,
                            median(row.shares()), meanOcclusion[i]);
            } else {
                std::printf("  %-8s %12.2f %13s %8s %12.2f %9.2f %11s %9s\n", "none", median(row.geometry), "-", "-",
                            median(row.lighting), frame, "-", "-");
            }
        }
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "ssao_benchmark: %s\n", error.what());
        return 1;
    }
}
