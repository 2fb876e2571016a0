// bvh_benchmark [--runs N]: lab 07's BVH with the solutions' code, on the
// generated statue (assets/generator's statueMesh(), as obj_load_benchmark makes
// it, here in memory) at 262,144 and 1,000,000 triangles. Prints:
//   (a) buildBvh() time (default settings) at both sizes: the median of N runs
//       (default 5), wall and thread CPU seconds, and the tree's size;
//   (b) primary rays at 262,144 triangles on one thread: 640x480 rays
//       (rayThroughPixel, pixel centres) from a camera 1 m from the statue's
//       head and chest (about half the rays hit), in Mrays/s (the median of N
//       passes; wall time, and the thread's CPU time beside it):
//         - intersectBvh() through the solution's tree;
//         - brute force (rayHitsTriangle over every triangle) on 2,000 rays spread
//           over the picture, one pass, extrapolated to Mrays/s;
//         - Embree 3's rtcIntersect1() (single rays, a device with "threads=1",
//           the same triangles, default build quality), when the build found it
//           (Debian/Ubuntu: libembree-dev, a benchmark-only dependency, not in
//           .ci/install-deps.sh); the ratio ours / Embree (goal >= 0.5x), and how
//           many rays agree with ours (same triangle, or t within 1e-4).
// Figures only, no pass/fail. Takes about 20 seconds (default runs).

#include "BenchmarkTiming.hpp"

#include "lab07.hpp"

#include <Geometry.hpp>

#include <stoa/geometry/Mesh.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#if defined(STOA_HAVE_EMBREE)
#include <embree3/rtcore.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using stoa::benchmark::median;

constexpr int kWidth = 640;
constexpr int kHeight = 480;
constexpr int kBruteForceRays = 2000;
constexpr double kEmbreeGoal = 0.5;

double threadSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

struct Seconds {
    double wall = 0.0, cpu = 0.0;
};

Seconds timed(const std::function<void()>& work) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = threadSeconds();
    work();
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), threadSeconds() - cpuStart};
}

Seconds median(const std::vector<Seconds>& runs) {
    std::vector<double> walls, cpus;
    for (const Seconds& run : runs) {
        walls.push_back(run.wall);
        cpus.push_back(run.cpu);
    }
    return {median(walls), median(cpus)};
}

// The statue with exactly 4 r^2 triangles (generateDenseStatue's resolution).
stoa::Mesh statue(int rings) { return stoa::assets::statueMesh(2 * rings, rings); }

// Its triangles; each one's object is its index in the mesh.
std::vector<stoa::Triangle> trianglesOf(const stoa::Mesh& mesh) {
    std::vector<stoa::Triangle> triangles;
    triangles.reserve(mesh.triangleCount());
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        stoa::Triangle triangle;
        triangle.p0 = mesh.vertices[mesh.indices[i]].position;
        triangle.p1 = mesh.vertices[mesh.indices[i + 1]].position;
        triangle.p2 = mesh.vertices[mesh.indices[i + 2]].position;
        triangle.object = static_cast<int>(i / 3);
        triangles.push_back(triangle);
    }
    return triangles;
}

struct TreeShape {
    int nodes = 0, leaves = 0, depth = 0, largestLeaf = 0;
};

TreeShape shapeOf(const stoa::Bvh& bvh) {
    TreeShape shape;
    shape.nodes = static_cast<int>(bvh.nodes.size());
    std::vector<std::pair<int, int>> stack{{0, 0}};
    while (!stack.empty()) {
        const auto [index, depth] = stack.back();
        stack.pop_back();
        const stoa::BvhNode& node = bvh.nodes[static_cast<std::size_t>(index)];
        shape.depth = std::max(shape.depth, depth);
        if (node.count > 0) {
            ++shape.leaves;
            shape.largestLeaf = std::max(shape.largestLeaf, node.count);
        } else {
            stack.push_back({node.first, depth + 1});
            stack.push_back({node.first + 1, depth + 1});
        }
    }
    return shape;
}

// What a ray hit: the mesh's triangle index and t, or -1.
struct Answer {
    int triangle = -1;
    float t = std::numeric_limits<float>::infinity();
};

bool agree(const Answer& a, const Answer& b) {
    if (a.triangle < 0 || b.triangle < 0) return a.triangle == b.triangle;
    return a.triangle == b.triangle || std::abs(a.t - b.t) <= 1e-4f * std::max(1.0f, a.t);
}

double agreement(const std::vector<Answer>& ours, const std::vector<Answer>& theirs, const std::vector<std::size_t>& which) {
    std::size_t same = 0;
    for (std::size_t k = 0; k < which.size(); ++k) same += agree(ours[which[k]], theirs[k]) ? 1 : 0;
    return 100.0 * static_cast<double>(same) / static_cast<double>(which.size());
}

void printRate(const char* name, std::size_t rays, const Seconds& seconds, const char* note) {
    std::printf("  %-30s %9.4g Mrays/s  (%.3f s wall for %zu rays; %.4g Mrays/s by thread CPU)%s\n", name,
                static_cast<double>(rays) / seconds.wall * 1e-6, seconds.wall, rays,
                static_cast<double>(rays) / seconds.cpu * 1e-6, note);
}

int usage() {
    std::fprintf(stderr, "usage: bvh_benchmark [--runs N]\n");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    int runs = 5;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--runs" && i + 1 < argc) {
            runs = std::atoi(argv[++i]);
            if (runs < 1) return usage();
        } else {
            return usage();
        }
    }
    std::printf("bvh_benchmark: lab 07's BVH (solutions), %d runs, the generated statue\n", runs);

    // (a) Build times.
    std::printf("(a) buildBvh(), default settings (12 bins, leaves <= 4), median of %d runs\n", runs);
    const stoa::Mesh small = statue(256);   // 262,144 triangles
    const std::vector<stoa::Triangle> smallTriangles = trianglesOf(small);
    const std::vector<stoa::Triangle> largeTriangles = trianglesOf(statue(500));   // 1,000,000
    for (const std::vector<stoa::Triangle>* set : {&smallTriangles, &largeTriangles}) {
        const std::vector<stoa::Triangle>& triangles = *set;
        std::vector<Seconds> times;
        TreeShape shape;
        for (int run = 0; run < runs; ++run) {
            std::vector<stoa::Triangle> copy = triangles;   // buildBvh takes its input by value: not timed
            stoa::Bvh bvh;
            times.push_back(timed([&] { bvh = stoa::buildBvh(std::move(copy)); }));
            if (run == 0) shape = shapeOf(bvh);
        }
        const Seconds build = median(times);
        std::printf("  %9zu triangles  %7.3f s wall  %7.3f s CPU  (%.2f Mtriangles/s; %d nodes, %d leaves, depth %d, "
                    "largest leaf %d)\n",
                    triangles.size(), build.wall, build.cpu, static_cast<double>(triangles.size()) / build.wall * 1e-6,
                    shape.nodes, shape.leaves, shape.depth, shape.largestLeaf);
    }

    // (b) Primary rays at 262,144 triangles.
    const stoa::Bvh bvh = stoa::buildBvh(smallTriangles);
    const glm::vec3 eye(0.3f, 1.45f, 0.95f), target(0.0f, 1.35f, 0.0f);   // the head and chest fill half the picture
    const glm::mat4 view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 projection = glm::perspective(glm::radians(40.0f), static_cast<float>(kWidth) / kHeight, 0.1f, 100.0f);
    const glm::mat4 inverseViewProjection = glm::inverse(projection * view);
    std::vector<stoa::Ray> rays;
    rays.reserve(static_cast<std::size_t>(kWidth) * kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            rays.push_back(stoa::rayThroughPixel({x + 0.5f, y + 0.5f}, {kWidth, kHeight}, inverseViewProjection));
    std::printf("(b) primary rays, %zu triangles, %dx%d = %zu rays from (%.2f, %.2f, %.2f) at the statue, 40 deg, one thread\n",
                smallTriangles.size(), kWidth, kHeight, rays.size(), eye.x, eye.y, eye.z);

    std::vector<Answer> ours(rays.size());
    std::vector<Seconds> passes;
    for (int run = 0; run < runs; ++run) {
        passes.push_back(timed([&] {
            for (std::size_t i = 0; i < rays.size(); ++i) {
                const stoa::Hit hit = stoa::intersectBvh(bvh, rays[i]);
                ours[i] = hit.found() ? Answer{bvh.triangles[static_cast<std::size_t>(hit.triangle)].object, hit.t} : Answer{};
            }
        }));
    }
    const Seconds oursTime = median(passes);
    const std::size_t hits = static_cast<std::size_t>(std::count_if(ours.begin(), ours.end(), [](const Answer& a) { return a.triangle >= 0; }));
    std::printf("  %.1f%% of the rays hit the statue\n", 100.0 * static_cast<double>(hits) / static_cast<double>(rays.size()));
    printRate("intersectBvh (ours)", rays.size(), oursTime, "");

    // Brute force on a subset spread over the picture.
    std::vector<std::size_t> subset;
    for (int k = 0; k < kBruteForceRays; ++k) subset.push_back(static_cast<std::size_t>(k) * rays.size() / kBruteForceRays);
    std::vector<Answer> brute(subset.size());
    const Seconds bruteTime = timed([&] {
        for (std::size_t k = 0; k < subset.size(); ++k) {
            stoa::Hit hit;
            for (std::size_t t = 0; t < smallTriangles.size(); ++t)
                if (stoa::rayHitsTriangle(rays[subset[k]], smallTriangles[t], hit)) hit.triangle = static_cast<int>(t);
            brute[k] = hit.found() ? Answer{hit.triangle, hit.t} : Answer{};
        }
    });
    printRate("brute force (every triangle)", subset.size(), bruteTime,
              "\n                                           (one pass over 2,000 of the rays, extrapolated)");
    std::printf("  %-30s %9.0fx  (agreement with ours on those rays: %.2f%%)\n", "ours / brute force",
                bruteTime.wall / static_cast<double>(subset.size()) / (oursTime.wall / static_cast<double>(rays.size())),
                agreement(ours, brute, subset));

#if defined(STOA_HAVE_EMBREE)
    {
        RTCDevice device = rtcNewDevice("threads=1");
        if (!device) {
            std::printf("  Embree 3: rtcNewDevice failed (error %d)\n", static_cast<int>(rtcGetDeviceError(nullptr)));
            return 0;
        }
        RTCScene scene = nullptr;
        std::vector<Seconds> builds;
        for (int run = 0; run < runs; ++run) {
            if (scene) rtcReleaseScene(scene);
            scene = rtcNewScene(device);
            builds.push_back(timed([&] {
                RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
                auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                             3 * sizeof(float), small.vertices.size()));
                for (std::size_t v = 0; v < small.vertices.size(); ++v) {
                    vertices[3 * v] = small.vertices[v].position.x;
                    vertices[3 * v + 1] = small.vertices[v].position.y;
                    vertices[3 * v + 2] = small.vertices[v].position.z;
                }
                auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                               3 * sizeof(unsigned), small.triangleCount()));
                std::copy(small.indices.begin(), small.indices.end(), indices);
                rtcCommitGeometry(geometry);
                rtcAttachGeometry(scene, geometry);
                rtcReleaseGeometry(geometry);
                rtcCommitScene(scene);
            }));
        }
        const Seconds embreeBuild = median(builds);
        std::vector<Answer> embree(rays.size());
        std::vector<std::size_t> all(rays.size());
        for (std::size_t i = 0; i < rays.size(); ++i) all[i] = i;
        passes.clear();
        for (int run = 0; run < runs; ++run) {
            passes.push_back(timed([&] {
                RTCIntersectContext context;
                rtcInitIntersectContext(&context);
                for (std::size_t i = 0; i < rays.size(); ++i) {
                    const stoa::Ray& ray = rays[i];
                    RTCRayHit query{};
                    query.ray.org_x = ray.origin.x;
                    query.ray.org_y = ray.origin.y;
                    query.ray.org_z = ray.origin.z;
                    query.ray.dir_x = ray.direction.x;
                    query.ray.dir_y = ray.direction.y;
                    query.ray.dir_z = ray.direction.z;
                    query.ray.tnear = 0.0f;
                    query.ray.tfar = std::numeric_limits<float>::infinity();
                    query.ray.mask = ~0u;
                    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                    rtcIntersect1(scene, &context, &query);
                    embree[i] = query.hit.geomID != RTC_INVALID_GEOMETRY_ID ? Answer{static_cast<int>(query.hit.primID), query.ray.tfar}
                                                                             : Answer{};
                }
            }));
        }
        const Seconds embreeTime = median(passes);
        printRate("Embree 3 rtcIntersect1", rays.size(), embreeTime, "");
        const double ratio = embreeTime.wall / oursTime.wall;
        std::printf("  %-30s %9.2fx  (goal >= %.1fx: %s)\n", "ours / Embree", ratio, kEmbreeGoal,
                    ratio >= kEmbreeGoal ? "met" : "not met");
        std::printf("  %-30s %9.2f%%  (same triangle, or t within 1e-4)\n", "hits agreeing with ours", agreement(ours, embree, all));
        std::printf("  %-30s %9.3f s wall  %.3f s CPU  (rtcCommitScene, default quality, median of %d; ours above)\n",
                    "Embree build, 262,144 triangles", embreeBuild.wall, embreeBuild.cpu, runs);
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
#else
    std::printf("  Embree 3 not found: install libembree-dev to compare\n");
#endif
    return 0;
}
