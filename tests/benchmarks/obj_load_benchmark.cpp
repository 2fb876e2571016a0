// obj_load_benchmark [--runs N] [--triangles T] [FILE.obj]: the time of
// stoa::loadObj() on a large mesh, as the median of N runs (default 5). Without
// FILE it generates the Acropolis statue with about T triangles (default
// 1000000, no normals: the loader computes them) into a temporary folder.
// Prints the median wall and CPU seconds, the triangle and vertex counts of the
// loaded model, and the throughput in MB/s of file size (by each median; on a
// shared machine the CPU time is the steadier figure).

#include "BenchmarkTiming.hpp"

#include <Acropolis.hpp>

#include <stoa/geometry/ObjLoader.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

using stoa::benchmark::median;

double threadSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

int usage() {
    std::fprintf(stderr, "usage: obj_load_benchmark [--runs N] [--triangles T] [FILE.obj]\n");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    int runs = 5, triangles = 1000000;
    fs::path file;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if ((argument == "--runs" || argument == "--triangles") && i + 1 < argc) {
            const int value = std::atoi(argv[++i]);
            if (value < 1) return usage();
            (argument == "--runs" ? runs : triangles) = value;
        } else if (argument[0] != '-' && file.empty()) {
            file = argument;
        } else {
            return usage();
        }
    }

    fs::path generatedFolder;
    try {
        if (file.empty()) {
            generatedFolder = fs::temp_directory_path() / ("stoa-obj-benchmark-" + std::to_string(::getpid()));
            file = stoa::assets::generateDenseStatue(generatedFolder, triangles);
        }
        const double megabytes = static_cast<double>(fs::file_size(file)) / 1e6;
        std::vector<double> walls, cpus;
        std::size_t triangleCount = 0, vertexCount = 0;
        for (int run = 0; run < runs; ++run) {
            const auto start = std::chrono::steady_clock::now();
            const double cpuStart = threadSeconds();
            const stoa::Model model = stoa::loadObj(file);
            cpus.push_back(threadSeconds() - cpuStart);
            walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            triangleCount = vertexCount = 0;
            for (const stoa::ModelPart& part : model.parts) {
                triangleCount += part.mesh.triangleCount();
                vertexCount += part.mesh.vertices.size();
            }
        }
        const double wall = median(walls), cpu = median(cpus);
        std::printf("obj_load_benchmark: %s (%.1f MB)\n", file.c_str(), megabytes);
        std::printf("  runs                 %d\n", runs);
        std::printf("  triangles            %zu\n", triangleCount);
        std::printf("  vertices             %zu\n", vertexCount);
        std::printf("  median wall seconds  %.3f\n", wall);
        std::printf("  median CPU seconds   %.3f\n", cpu);
        std::printf("  throughput           %.1f MB/s (file size / median wall time)\n", megabytes / wall);
        std::printf("                       %.1f MB/s (file size / median CPU time: one core, whatever else runs)\n",
                    megabytes / cpu);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "obj_load_benchmark: %s\n", error.what());
        if (!generatedFolder.empty()) {
            std::error_code ignored;
            fs::remove_all(generatedFolder, ignored);
        }
        return 1;
    }
    if (!generatedFolder.empty()) {
        std::error_code ignored;
        fs::remove_all(generatedFolder, ignored);
    }
    return 0;
}
