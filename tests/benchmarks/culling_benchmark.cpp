// culling_benchmark [--runs N] [--full-runs M]: lab 06's culling and levels of
// detail with the solutions' code, on a field of 10,000 columns
// (assets/acropolis/column.obj, 3,960 triangles; levels from
// buildLevelsOfDetail(column, {1, 0.3, 0.1, 0.03}, 0.2)) jittered on a 10 m grid
// 1000 m square, seen by a camera in the middle at eye height (50 deg, 16:9,
// far plane 350 m) that sees about a tenth of them. Two tables:
//   (a) the CPU cost of culling, per object: frustumPlanes() once, then
//       sphereInFrustum() for every object; the same with boxInFrustum(); and
//       the whole decision as the app makes it (sphere, then the box of those it
//       keeps, then lodQuality() and levelOfDetail() of those visible), in ns per
//       object, the median of N runs (default 7) of many passes each.
//       Goal: <= 20 ns per object.
//   (b) the frame time at 1280x720 on the headless context (llvmpipe), drawn
//       with shaders/basic/lit.vert and lit.frag: every column at full detail, the
//       visible ones at full detail (culling alone), and the visible ones at
//       their level (culling + levels of detail, default LodSettings; the
//       decisions are made inside the timed frame). Each ends with glFinish().
//       The culled frames are the median of N rounds; the full-detail frame
//       (~40M triangles: seconds on llvmpipe) of M rounds (default 3), taking
//       turns with them. Goal: full detail / (culling + levels) >= 5x.
// The culled picture is checked to be the full-detail one (culling drops only
// what is off the screen). $STOA_PREVIEW_DIR: the pictures are saved there.
// $STOA_HEADLESS picks the backend, $LP_NUM_THREADS llvmpipe's threads.

#include "BenchmarkTiming.hpp"

#include "lab06.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/LevelOfDetail.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/TextureCache.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/image/ImageCompare.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/DrawList.hpp>
#include <stoa/scene/ObjectUniforms.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

using stoa::benchmark::Clock;
using stoa::benchmark::median;
using stoa::benchmark::milliseconds;

constexpr int kWidth = 1280;
constexpr int kHeight = 720;
constexpr int kSide = 100;             // kSide x kSide columns
constexpr float kSpacing = 10.0f;      // metres: the field is kSide * kSpacing = 1000 m square
constexpr float kFovYDegrees = 50.0f;
constexpr float kNear = 0.5f;
constexpr float kFar = 350.0f;         // the camera sees about a tenth of the field
constexpr double kCpuGoalNs = 20.0;
constexpr double kFrameGoalRatio = 5.0;

// The lab's generator (Numerical Recipes' LCG): the same field everywhere.
class FieldRandom {
public:
    explicit FieldRandom(std::uint32_t seed) : m_state(seed) {}
    float uniform(float low, float high) {
        m_state = m_state * 1664525u + 1013904223u;
        return low + (high - low) * static_cast<float>(m_state >> 8) / 16777216.0f;
    }

private:
    std::uint32_t m_state;
};

struct Column {
    glm::mat4 model{1.0f};
    glm::mat3 normalMatrix{1.0f};
    stoa::BoundingSphere sphere;   // world
    stoa::Aabb box;                // world
};

struct View {
    glm::vec3 eye{0.0f, 1.7f, 0.0f};
    glm::mat4 view{1.0f}, projection{1.0f};
    glm::mat4 viewProjection() const { return projection * view; }
};

View camera() {
    View v;
    v.view = glm::lookAt(v.eye, v.eye + glm::vec3(0.0f, -0.02f, 1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    v.projection = glm::perspective(glm::radians(kFovYDegrees), static_cast<float>(kWidth) / kHeight, kNear, kFar);
    return v;
}

// Columns on a jittered grid, turned and stretched as the lab's (non-uniform
// scales); none within 4 m of the eye.
std::vector<Column> buildField(const stoa::BoundingSphere& objectSphere, const stoa::Bounds& objectBounds,
                               const glm::vec3& eye) {
    std::vector<Column> field;
    FieldRandom random(6);
    const float start = -0.5f * kSpacing * (kSide - 1);
    for (int i = 0; i < kSide; ++i)
        for (int j = 0; j < kSide; ++j) {
            glm::vec3 position(start + kSpacing * i + random.uniform(-3.0f, 3.0f), 0.0f,
                               start + kSpacing * j + random.uniform(-3.0f, 3.0f));
            const float yaw = random.uniform(0.0f, 360.0f);
            const float size = random.uniform(0.8f, 1.3f);
            const float stretch = random.uniform(0.6f, 1.8f);
            if (glm::length(glm::vec2(position.x - eye.x, position.z - eye.z)) < 4.0f) position.x += 8.0f;
            glm::mat4 model = glm::translate(glm::mat4(1.0f), position);
            model = glm::rotate(model, glm::radians(yaw), glm::vec3(0.0f, 1.0f, 0.0f));
            model = glm::scale(model, glm::vec3(size, size * stretch, size));
            Column column;
            column.model = model;
            column.normalMatrix = glm::inverseTranspose(glm::mat3(model));
            column.sphere = stoa::worldBoundingSphere(objectSphere, model);
            column.box = stoa::transformed(objectBounds, model).box;
            field.push_back(column);
        }
    return field;
}

volatile long long g_sink = 0;   // keeps the timed loops' results alive

// (a) Nanoseconds per object of `pass` (one pass over the field, returning a
// count), the median of `runs` runs of `passes` passes each.
double nsPerObject(const std::function<long long()>& pass, int runs, int passes, std::size_t objects) {
    pass();   // warm-up
    std::vector<double> ns;
    for (int run = 0; run < runs; ++run) {
        const auto start = Clock::now();
        long long total = 0;
        for (int p = 0; p < passes; ++p) total += pass();
        const auto end = Clock::now();
        g_sink = g_sink + total;
        ns.push_back(milliseconds(start, end) * 1e6 / (static_cast<double>(passes) * objects));
    }
    return median(ns);
}

void cpuTable(const std::vector<Column>& field, const View& view, int levelCount, int runs) {
    const std::size_t n = field.size();
    const glm::mat4 viewProjection = view.viewProjection();
    const stoa::LodSettings settings;
    const int passes = 200;

    const auto spheres = [&] {
        const stoa::Frustum frustum = stoa::frustumPlanes(viewProjection);
        long long kept = 0;
        for (const Column& c : field) kept += stoa::sphereInFrustum(frustum, c.sphere);
        return kept;
    };
    const auto boxes = [&] {
        const stoa::Frustum frustum = stoa::frustumPlanes(viewProjection);
        long long kept = 0;
        for (const Column& c : field) kept += stoa::boxInFrustum(frustum, c.box);
        return kept;
    };
    std::vector<int> levelCounts(levelCount + 1, 0);   // [0]: hidden (level -1), [k + 1]: level k
    const auto decide = [&](bool count) {
        const stoa::Frustum frustum = stoa::frustumPlanes(viewProjection);
        long long drawn = 0;
        for (const Column& c : field) {
            if (!stoa::sphereInFrustum(frustum, c.sphere) || !stoa::boxInFrustum(frustum, c.box)) continue;
            const int level = stoa::levelOfDetail(
                stoa::lodQuality(c.sphere, view.eye, kFovYDegrees, kHeight, settings), levelCount);
            drawn += level >= 0;
            if (count) ++levelCounts[std::clamp(level, -1, levelCount - 1) + 1];
        }
        return drawn;
    };

    const long long sphereKept = spheres(), boxKept = boxes();
    const long long drawn = decide(true);
    long long bothKept = 0;
    for (int count : levelCounts) bothKept += count;

    const double sphereNs = nsPerObject(spheres, runs, passes, n);
    const double boxNs = nsPerObject(boxes, runs, passes, n);
    const double allNs = nsPerObject([&] { return decide(false); }, runs, passes, n);

    std::printf("(a) CPU cost of culling, %zu objects in a 1000 m square, median of %d runs of %d passes\n", n, runs,
                passes);
    std::printf("    (frustumPlanes() once per pass; the time divided by every object of the field)\n");
    std::printf("  %-44s %10s %8s  %s\n", "", "ns/object", "goal", "");
    const auto row = [](const char* name, double ns) {
        std::printf("  %-44s %10.2f %8s  %s\n", name, ns, "<= 20", ns <= kCpuGoalNs ? "ok" : "OVER");
    };
    row("sphereInFrustum", sphereNs);
    row("boxInFrustum", boxNs);
    row("sphere, box, lodQuality + levelOfDetail", allNs);
    std::printf("  visible: sphere %.1f%%, box %.1f%%, both %.1f%% (%lld); drawn (level >= 0) %lld\n",
                100.0 * sphereKept / n, 100.0 * boxKept / n, 100.0 * bothKept / n, bothKept, drawn);
    std::printf("  levels of the visible ones: hidden (-1): %d", levelCounts[0]);
    for (int level = 0; level < levelCount; ++level) std::printf(", L%d: %d", level, levelCounts[level + 1]);
    std::printf("\n\n");
}

// --- (b) ------------------------------------------------------------------

struct Measured {
    const char* name;
    std::function<void()> frame;
    int rounds = 0;
    std::vector<double> ms;
    std::size_t objects = 0, triangles = 0;   // drawn in the last frame
};

} // namespace

int main(int argc, char** argv) {
    int runs = 7, fullRuns = 3;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
        else if (std::strcmp(argv[i], "--full-runs") == 0 && i + 1 < argc) fullRuns = std::max(1, std::atoi(argv[++i]));
        else {
            std::fprintf(stderr, "usage: culling_benchmark [--runs N] [--full-runs M]\n");
            return 2;
        }
    }
    fullRuns = std::min(fullRuns, runs);
    std::printf("culling_benchmark");
    for (int i = 1; i < argc; ++i) std::printf(" %s", argv[i]);
    std::printf("\n");
    try {
        stoa::HeadlessContext context;
        std::printf("%s\n\n", context.description().c_str());

        const stoa::Model model = stoa::loadObj(stoa::paths::assetsDir() / "acropolis" / "column.obj");
        const stoa::Mesh& column = model.parts.front().mesh;
        const stoa::Material& material = model.parts.front().material;
        const std::vector<stoa::LodLevel> lods = stoa::buildLevelsOfDetail(column, {1.0f, 0.3f, 0.1f, 0.03f}, 0.2f);
        std::vector<std::unique_ptr<stoa::GpuMesh>> levels;
        std::vector<std::size_t> levelTriangles;
        for (const stoa::LodLevel& level : lods) {
            levels.push_back(std::make_unique<stoa::GpuMesh>(level.mesh));
            levelTriangles.push_back(level.mesh.triangleCount());
        }
        const int levelCount = static_cast<int>(levels.size());

        const View view = camera();
        const stoa::BoundingSphere objectSphere = stoa::meshBoundingSphere(column);
        const std::vector<Column> field = buildField(objectSphere, levels.front()->bounds(), view.eye);

        cpuTable(field, view, levelCount, runs);

        // (b) The frame, as lab 06's app draws its field.
        const stoa::Program program = stoa::Program::fromFiles("basic/lit.vert", "basic/lit.frag",
                                                               {stoa::paths::shadersDir()});
        program.bindUniformBlock(stoa::FrameUniforms::kBlockName, stoa::FrameUniforms::kBinding);
        const stoa::ObjectUniforms uniforms(program);
        std::shared_ptr<const stoa::Texture2D> diffuseMap;
        if (!material.diffuseMap.empty()) diffuseMap = stoa::TextureCache::shared().load(material.diffuseMap);
        stoa::FrameUniforms frame;
        stoa::FrameBlock block{};
        block.view = view.view;
        block.projection = view.projection;
        block.cameraPosition = view.eye;
        block.ambient = glm::vec3(0.35f, 0.37f, 0.42f);
        const stoa::DirectionalLight sun = stoa::acropolisSun();
        block.directionalLightCount = 1;
        block.directionalLights[0].direction = sun.direction;
        block.directionalLights[0].color = sun.color;
        block.pointLightCount = 0;
        const stoa::Framebuffer target(kWidth, kHeight);
        target.bind();

        const auto beginFrame = [&] {
            frame.update(block);
            frame.bind();
            stoa::PassDescription pass = stoa::passInto(glm::ivec2(kWidth, kHeight));
            pass.clear.color = pass.clear.depth = true;
            pass.clear.colorValue = glm::vec4(0.05f, 0.06f, 0.08f, 1.0f);
            pass.state.cull = stoa::CullMode::None;   // as the lab
            stoa::beginPass(pass);
            program.use();
            program.set("uTint", glm::vec3(0.0f));
            program.set("uTintAmount", 0.0f);
        };
        const auto drawColumn = [&](const Column& c, int level) {
            stoa::DrawItem item;
            item.mesh = levels[level].get();
            item.model = c.model;
            item.normalMatrix = c.normalMatrix;
            item.material = &material;
            item.diffuseMap = diffuseMap.get();
            uniforms.apply(item);
            item.mesh->draw();
        };
        // The decisions of the culled frames, made inside the frame.
        const auto culledFrame = [&](bool withLevels, Measured& m) {
            beginFrame();
            const stoa::Frustum frustum = stoa::frustumPlanes(view.viewProjection());
            const stoa::LodSettings settings;
            m.objects = m.triangles = 0;
            for (const Column& c : field) {
                if (!stoa::sphereInFrustum(frustum, c.sphere) || !stoa::boxInFrustum(frustum, c.box)) continue;
                int level = 0;
                if (withLevels) {
                    level = stoa::levelOfDetail(stoa::lodQuality(c.sphere, view.eye, kFovYDegrees, kHeight, settings),
                                                levelCount);
                    if (level < 0) continue;
                }
                drawColumn(c, level);
                ++m.objects;
                m.triangles += levelTriangles[level];
            }
        };
        std::vector<Measured> measurements(3);
        measurements[0] = {"everything at full detail", {}, fullRuns, {}, 0, 0};
        measurements[0].frame = [&] {
            beginFrame();
            for (const Column& c : field) drawColumn(c, 0);
            measurements[0].objects = field.size();
            measurements[0].triangles = field.size() * levelTriangles[0];
        };
        measurements[1] = {"culling, full detail", {}, runs, {}, 0, 0};
        measurements[1].frame = [&] { culledFrame(false, measurements[1]); };
        measurements[2] = {"culling + levels of detail", {}, runs, {}, 0, 0};
        measurements[2].frame = [&] { culledFrame(true, measurements[2]); };

        std::vector<stoa::Image> pictures;
        for (Measured& m : measurements) {   // warm-up, and the pictures
            m.frame();
            glFinish();
            pictures.push_back(target.readColor());
        }
        for (int round = 0; round < runs; ++round)
            for (Measured& m : measurements) {
                if (round >= m.rounds) continue;
                glFinish();
                const auto start = Clock::now();
                m.frame();
                glFinish();
                m.ms.push_back(milliseconds(start, Clock::now()));
            }

        std::printf("(b) frame time, %d columns (levels: %zu / %zu / %zu / %zu triangles), %dx%d on the headless context\n",
                    kSide * kSide, levelTriangles[0], levelTriangles[1], levelTriangles[2], levelTriangles[3], kWidth,
                    kHeight);
        std::printf("    (full detail: median of %d rounds only, about a second each; the culled frames: median of %d rounds;\n"
                    "     the culled frames include their decisions; every frame ends with glFinish())\n",
                    fullRuns, runs);
        std::printf("  %-28s %8s %12s %10s %8s\n", "", "objects", "triangles", "frame ms", "speed-up");
        const double full = median(measurements[0].ms);
        for (const Measured& m : measurements)
            std::printf("  %-28s %8zu %12zu %10.1f %7.1fx\n", m.name, m.objects, m.triangles, median(m.ms),
                        full / median(m.ms));
        const double ratio = full / median(measurements[2].ms);
        std::printf("  full detail / (culling + levels of detail): %.1fx (goal >= %.0fx: %s)\n", ratio, kFrameGoalRatio,
                    ratio >= kFrameGoalRatio ? "ok" : "BELOW");
        const stoa::CompareResult same = stoa::compareImages(pictures[1], pictures[0], stoa::CompareOptions{});
        std::printf("  culled picture vs full detail: %s (%s)\n", same.passed ? "the same" : "DIFFERENT",
                    same.summary.c_str());
        const stoa::CompareResult lod = stoa::compareImages(pictures[2], pictures[0], stoa::CompareOptions{});
        std::printf("  with levels of detail vs full detail (informational): %s\n", lod.summary.c_str());
        if (const char* folder = std::getenv("STOA_PREVIEW_DIR")) {
            pictures[0].savePng(std::filesystem::path(folder) / "culling_full_detail.png");
            pictures[1].savePng(std::filesystem::path(folder) / "culling_culled.png");
            pictures[2].savePng(std::filesystem::path(folder) / "culling_culled_lod.png");
        }
        return same.passed ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "culling_benchmark: %s\n", error.what());
        return 1;
    }
}
