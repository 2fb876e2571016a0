#pragma once
// Cases of tests/grader/hostile_lab.cpp, which misbehaves in the way each case's
// name says ("infinite_loop", "segfault", "daemon_rewrite", ...; "good" renders).

#include "CaseRunner.hpp"

#include <stoa/image/Image.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace stoa::test {

inline const char* const kHostileLab = STOA_HOSTILE_LAB;

/// The picture hostile_lab's "good" case renders.
inline Image gradient(int width, int height) {
    Image image(width, height, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.setPixel(x, y, {static_cast<std::uint8_t>(x * 16), static_cast<std::uint8_t>(y * 16), 128, 255});
    return image;
}

/// One 16x16 case of the hostile lab program, worth 1 point, working in
/// <work>/<name>, with a gradient written as its reference <references>/<name>.png.
inline grader::CaseJob hostileJob(const std::string& name, const std::filesystem::path& references,
                                  const std::filesystem::path& work) {
    grader::CaseJob job;
    job.lab = "99_hostile";
    job.program = kHostileLab;
    job.spec.name = name;
    job.spec.width = 16;
    job.spec.height = 16;
    job.spec.points = 1;
    job.reference = references / (name + ".png");
    job.workDir = work / name;
    std::filesystem::create_directories(references);
    gradient(16, 16).savePng(job.reference);
    return job;
}

} // namespace stoa::test
