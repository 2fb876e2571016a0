// flip_benchmark [RUNS]: the time of computeFlip() on one core for 256^2, 512^2
// and 1024^2 images, as the median of RUNS runs (default 7), and its ratio to
// the shift-tolerant gate (compareImages() on a pair that differs in every
// row but only within the tolerance, so the gate searches every pixel and
// FLIP is skipped); the ratio is of CPU times. The target: 512x512 within 0.1 s
// of one core in a RelWithDebInfo build.

#include <stoa/image/Flip.hpp>
#include <stoa/image/ImageCompare.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <vector>

namespace {

// Something like a render: a shaded background, discs with soft shading and sharp edges.
stoa::Image scene(int size, int shift) {
    stoa::Image image(size, size, 4);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double u = double(x) / size, v = double(y) / size;
            double r = 40 + 60 * v, g = 50 + 40 * u, b = 90 + 50 * v;
            for (int disc = 0; disc < 5; ++disc) {
                const double cx = 0.2 + 0.15 * disc + shift * 1.0 / size, cy = 0.3 + 0.1 * (disc % 3);
                const double d = std::hypot(u - cx, v - cy) / 0.09;
                if (d < 1.0) {
                    const double shade = std::sqrt(1.0 - d * d);
                    r = 200 * shade + 20 * disc;
                    g = 120 * shade;
                    b = 60 + 30 * disc * shade;
                }
            }
            image.setPixel(x, y, {std::uint8_t(std::min(255.0, r)), std::uint8_t(std::min(255.0, g)),
                                  std::uint8_t(std::min(255.0, b)), 255});
        }
    return image;
}

double threadSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return now.tv_sec + now.tv_nsec * 1e-9;
}

struct Timing {
    double wall, cpu;  // medians, seconds
};

// Wall time and this thread's CPU time (the machines are shared: the CPU time is
// what one core spends, the wall time grows when others run).
Timing median(int runs, const std::function<void()>& work) {
    std::vector<double> walls, cpus;
    for (int i = 0; i < runs; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const double cpuStart = threadSeconds();
        work();
        cpus.push_back(threadSeconds() - cpuStart);
        walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(walls.begin(), walls.end());
    std::sort(cpus.begin(), cpus.end());
    return {walls[walls.size() / 2], cpus[cpus.size() / 2]};
}

} // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    std::printf("medians of %d runs, one thread; cpu = this thread's CPU time, wall = elapsed\n", runs);
    std::printf("%-10s %10s %10s %10s %10s %8s %10s\n", "size", "FLIP cpu", "FLIP wall", "gate cpu", "gate wall",
                "ratio", "FLIP mean");
    for (const int size : {256, 512, 1024}) {
        const stoa::Image reference = scene(size, 0);
        const stoa::Image test = scene(size, 2);  // discs moved by two pixels
        stoa::Image rounded = reference;           // +-2 levels everywhere: the gate's full search
        for (std::size_t i = 0; i < rounded.sizeInBytes(); ++i)
            if (i % 4 != 3) rounded.data()[i] = std::uint8_t(std::clamp(int(rounded.data()[i]) + int(i % 5) - 2, 0, 255));
        double mean = 0.0;
        const Timing flip = median(runs, [&] { mean = stoa::computeFlip(test, reference).mean; });
        const Timing gate = median(runs, [&] {
            const stoa::CompareResult result = stoa::compareImages(rounded, reference);
            if (result.flipMean != 0.0) std::printf("unexpected: FLIP ran on the rounded pair\n");
        });
        std::printf("%4dx%-5d %10.4f %10.4f %10.4f %10.4f %8.1f %10.4f\n", size, size, flip.cpu, flip.wall, gate.cpu,
                    gate.wall, flip.cpu / gate.cpu, mean);
    }
    return 0;
}
