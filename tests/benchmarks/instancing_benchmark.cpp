// instancing_benchmark [RUNS]: 10,000 copies of a ~500-triangle sphere at
// 1280x720 on the headless context (llvmpipe), drawn two ways, the median of
// RUNS rounds (default 7, after a warm-up round; the two take turns):
//   - per object: a Scene of 10,000 MeshObjects sharing one GpuMesh, through
//     ForwardRenderer (a DrawList, per-object uniforms by location, one draw
//     each; the model matrices are lab 01's solution code);
//   - per object by name: the same draws with every per-object uniform set by
//     name (Program::set(), a hashed look-up each), as objects drew themselves
//     before the DrawList;
//   - instanced: one InstancedMesh of 10,000 instances, one draw call (the
//     instances uploaded every frame, as moving agents would be).
// The same again with a 12-triangle cube, where the draws' own cost shows.
// For each: the CPU time of submitting the frame (from the start until the
// last GL call returns, before glFinish()) and the frame time (until glFinish()
// returns: llvmpipe has drawn it), in wall milliseconds. Both pictures are
// checked to be the same within a few levels (the instanced shader takes the
// normal matrix as the model's 3x3, which is right for these uniform scales).
// $STOA_HEADLESS picks the backend, $LP_NUM_THREADS llvmpipe's threads.

#include "BenchmarkTiming.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/image/ImageCompare.hpp>
#include "lab01.hpp"
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/render/InstancedMesh.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/Scene.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace {

using stoa::benchmark::Clock;
using stoa::benchmark::median;
using stoa::benchmark::milliseconds;

constexpr int kWidth = 1280;
constexpr int kHeight = 720;
constexpr int kSide = 100;   // kSide x kSide objects
constexpr float kSpacing = 1.2f;

struct Measured {
    const char* name;
    std::function<void()> submit;   // issues the frame's GL calls
    std::vector<double> submitMs, frameMs;
};

glm::vec3 colorOf(int i, int j) {
    return {0.3f + 0.7f * static_cast<float>(i) / kSide, 0.4f, 0.3f + 0.7f * static_cast<float>(j) / kSide};
}

glm::vec3 positionOf(int i, int j) {
    return {(static_cast<float>(i) - 0.5f * kSide) * kSpacing, 0.0f, (static_cast<float>(j) - 0.5f * kSide) * kSpacing};
}

// One table: the three ways of drawing kSide^2 copies of `mesh`. Returns
// whether the per-object and instanced pictures agree.
bool runTable(const stoa::Mesh& mesh, const char* what, int runs, const stoa::Program& perObject,
              const stoa::Program& instanced, const stoa::Framebuffer& target) {
    stoa::Scene scene;
    scene.ambient = glm::vec3(0.2f);
    scene.directionalLights.push_back({{-0.4f, -1.0f, -0.3f}, glm::vec3(0.9f)});
    auto shared = std::make_shared<const stoa::GpuMesh>(mesh);
    std::vector<stoa::Instance> instances;
    for (int i = 0; i < kSide; ++i)
        for (int j = 0; j < kSide; ++j) {
            stoa::Material material;
            material.diffuse = colorOf(i, j);
            auto& object = scene.add(std::make_unique<stoa::MeshObject>(shared, material));
            object.position = positionOf(i, j);
            instances.push_back({stoa::modelMatrix(positionOf(i, j), glm::vec3(0.0f), glm::vec3(1.0f)),
                                 glm::vec4(colorOf(i, j), 1.0f)});
        }
    stoa::InstancedMesh crowd(mesh);
    const stoa::OrbitCamera camera({0.0f, 0.0f, 0.0f}, 95.0f, 0.0f, 55.0f);
    target.bind();
    const glm::ivec2 size(kWidth, kHeight);
    stoa::ForwardRenderer renderer;
    stoa::FrameUniforms frame;
    instanced.bindUniformBlock(stoa::FrameUniforms::kBlockName, stoa::FrameUniforms::kBinding);
    perObject.bindUniformBlock(stoa::FrameUniforms::kBlockName, stoa::FrameUniforms::kBinding);
    const auto beginFrame = [&] {
        stoa::PassDescription pass = stoa::passInto(size);
        pass.clear.color = pass.clear.depth = true;
        pass.clear.colorValue = glm::vec4(renderer.clearColor, 1.0f);
        stoa::beginPass(pass);
        frame.update(camera, static_cast<float>(kWidth) / kHeight, scene);
        frame.bind();
    };

    std::vector<Measured> measurements{
        {"per-object draws", [&] { renderer.render(scene, camera, perObject, size); }, {}, {}},
        {"per-object by name", [&] {
             beginFrame();
             perObject.use();
             for (const auto& object : scene.objects()) {
                 const auto& meshObject = static_cast<const stoa::MeshObject&>(*object);
                 perObject.set("uModel", meshObject.modelMatrix());
                 perObject.set("uNormalMatrix", meshObject.normalMatrix());
                 perObject.set("uMaterial.ambient", meshObject.material.ambient);
                 perObject.set("uMaterial.diffuse", meshObject.material.diffuse);
                 perObject.set("uMaterial.specular", meshObject.material.specular);
                 perObject.set("uMaterial.shininess", meshObject.material.shininess);
                 meshObject.mesh().draw();
             }
         }, {}, {}},
        {"instanced", [&] {
             beginFrame();
             instanced.use();
             crowd.setInstances(instances);
             crowd.draw();
         }, {}, {}},
    };
    std::printf("%d objects of %s (%zu triangles each), %dx%d, median of %d interleaved rounds\n", kSide * kSide,
                what, mesh.triangleCount(), kWidth, kHeight, runs);
    std::vector<stoa::Image> pictures;
    for (Measured& m : measurements) {   // warm-up, and the pictures to compare
        m.submit();
        glFinish();
        pictures.push_back(target.readColor());
    }
    for (int round = 0; round < runs; ++round)
        for (Measured& m : measurements) {
            glFinish();
            const auto start = Clock::now();
            m.submit();
            const auto submitted = Clock::now();
            glFinish();
            const auto finished = Clock::now();
            m.submitMs.push_back(milliseconds(start, submitted));
            m.frameMs.push_back(milliseconds(start, finished));
        }
    std::printf("  %-18s %14s %12s\n", "", "CPU submit ms", "frame ms");
    for (const Measured& m : measurements)
        std::printf("  %-18s %14.2f %12.2f\n", m.name, median(m.submitMs), median(m.frameMs));
    std::printf("  per-object / instanced: submit %.2fx, frame %.2fx; per-object draws: %zu\n",
                median(measurements[0].submitMs) / median(measurements[2].submitMs),
                median(measurements[0].frameMs) / median(measurements[2].frameMs), renderer.drawnCount());
    const stoa::CompareResult same = stoa::compareImages(pictures[2], pictures[0], stoa::CompareOptions{});
    std::printf("  the two pictures: %s (%s)\n\n", same.passed ? "the same" : "DIFFERENT", same.summary.c_str());
    if (const char* folder = std::getenv("STOA_PREVIEW_DIR")) {
        pictures[0].savePng(std::filesystem::path(folder) / (std::string("instancing_per_object_") + what + ".png"));
        pictures[2].savePng(std::filesystem::path(folder) / (std::string("instancing_instanced_") + what + ".png"));
    }
    return same.passed;
}

} // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    try {
        stoa::HeadlessContext context;
        const std::vector<std::filesystem::path> searchPath{stoa::paths::shadersDir()};
        const stoa::Program perObject =
            stoa::Program::fromFiles("instanced/per_object.vert", "instanced/instanced.frag", searchPath);
        const stoa::Program instanced =
            stoa::Program::fromFiles("instanced/instanced.vert", "instanced/instanced.frag", searchPath);
        const stoa::Framebuffer target(kWidth, kHeight);
        std::printf("instancing_benchmark: %s\n", context.description().c_str());
        // The sphere is the benchmark; the cube shows the cost of the draws
        // themselves, where llvmpipe's vertex work (done while submitting) is small.
        const bool sphere = runTable(stoa::shapes::sphere(0.5f, 18, 15), "a sphere", runs, perObject, instanced, target);
        const bool cube = runTable(stoa::shapes::cube(0.8f), "a cube", runs, perObject, instanced, target);
        return sphere && cube ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "instancing_benchmark: %s\n", error.what());
        return 1;
    }
}
