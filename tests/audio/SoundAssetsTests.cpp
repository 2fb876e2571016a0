// The generated sounds (assets/sounds/*.ogg): they are what the generator
// writes (compared as decoded sound: another libvorbis may encode the same
// samples in other bytes), they stay small, and the wind loops without a click.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <Sounds.hpp>

#include <stoa/audio/SoundClip.hpp>
#include <stoa/core/Paths.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

using namespace stoa;
namespace fs = std::filesystem;

namespace {

const fs::path committedDir = paths::assetsDir() / "sounds";

std::string readBytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

/// The RMS of each 20 ms window: the clip's loudness over time.
std::vector<double> envelope(const SoundClip& clip) {
    const std::size_t window = std::size_t(clip.sampleRate()) / 50;
    std::vector<double> out;
    for (std::size_t start = 0; start + window <= clip.frameCount(); start += window) {
        double sum = 0.0;
        for (std::size_t i = start; i < start + window; ++i) sum += std::pow(clip.samples()[i] / 32768.0, 2);
        out.push_back(std::sqrt(sum / double(window)));
    }
    return out;
}

/// |s[i+1] - s[i]| at the given fraction (0.99: the 99th percentile) of all neighbours.
double neighbourStep(const std::vector<std::int16_t>& s, double fraction) {
    std::vector<int> steps;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) steps.push_back(std::abs(int(s[i + 1]) - int(s[i])));
    std::sort(steps.begin(), steps.end());
    return steps[std::size_t(fraction * double(steps.size() - 1))];
}

} // namespace

TEST_CASE("The generator reproduces the committed sounds", "[audio][assets]") {
    test::TempFolder folder("sounds");
    assets::generateSounds(folder.path());
    for (const std::string& name : assets::soundFileNames()) {
        INFO(name << ": regenerate with bin/stoa-generate-assets --sounds assets/sounds (assets/README.md)");
        REQUIRE(fs::exists(committedDir / name));
        CHECK(fs::file_size(folder / name) < 60 * 1024);
        if (readBytes(folder / name) == readBytes(committedDir / name)) continue;
        // Sound, not bytes: another libvorbis may encode the same samples differently.
        WARN(name << " differs in its bytes from the committed file; comparing the decoded sound");
        const SoundClip mine = SoundClip::fromFile(folder / name), committed = SoundClip::fromFile(committedDir / name);
        REQUIRE(mine.frameCount() == committed.frameCount());
        const std::vector<double> a = envelope(mine), b = envelope(committed);
        for (std::size_t i = 0; i < a.size(); ++i) {
            INFO("window " << i << " (20 ms each): " << a[i] << " vs " << b[i]);
            CHECK(std::fabs(a[i] - b[i]) <= 0.2 * std::max(a[i], b[i]) + 0.005);
        }
    }
}

TEST_CASE("Encoding keeps each generated sound's loudness over time", "[audio][assets]") {
    for (const std::string& file : assets::soundFileNames()) {
        INFO(file);
        const std::string name = fs::path(file).stem().string();
        const SoundClip synthesized = assets::synthesizeSound(name);
        const SoundClip decoded = SoundClip::fromFile(committedDir / file);
        REQUIRE(decoded.frameCount() == synthesized.frameCount());
        const std::vector<double> a = envelope(synthesized), b = envelope(decoded);
        for (std::size_t i = 0; i < a.size(); ++i) {
            INFO("window " << i << " (20 ms each): synthesized " << a[i] << ", decoded " << b[i]);
            CHECK(std::fabs(a[i] - b[i]) <= 0.35 * std::max(a[i], b[i]) + 0.01);
        }
    }
}

TEST_CASE("The one-shot sounds start loud and fade out", "[audio][assets]") {
    for (const char* name : {"footstep", "spark"}) {
        INFO(name);
        const std::vector<double> loudness = envelope(assets::synthesizeSound(name));
        const double loudest = *std::max_element(loudness.begin(), loudness.end());
        CHECK(std::max_element(loudness.begin(), loudness.end()) - loudness.begin() < 5);   // within 100 ms
        CHECK(loudness.back() < 0.02 * loudest);
    }
}

TEST_CASE("The wind loops without a click", "[audio][assets]") {
    const SoundClip wind = assets::synthesizeSound("ambient_wind");
    const std::vector<std::int16_t>& s = wind.samples();
    // The step from the last sample back to the first is no larger than a
    // typical step inside the clip.
    const double seam = std::abs(int(s.front()) - int(s.back()));
    CHECK(seam <= neighbourStep(s, 0.9));
    // The same for the committed file, as the decoder gives it back.
    const SoundClip decoded = SoundClip::fromFile(committedDir / "ambient_wind.ogg");
    const std::vector<std::int16_t>& d = decoded.samples();
    CHECK(std::abs(int(d.front()) - int(d.back())) <= neighbourStep(d, 0.9));
    // And the loudness goes on across the seam: no dip or bump.
    const std::vector<double> loudness = envelope(wind);
    CHECK(std::fabs(loudness.front() - loudness.back()) < 0.3 * std::max(loudness.front(), loudness.back()));
    const double quietest = *std::min_element(loudness.begin(), loudness.end());
    CHECK(quietest > 0.1 * *std::max_element(loudness.begin(), loudness.end()));   // wind, never silence
}
