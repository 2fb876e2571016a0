#pragma once
// A made-up kind of asset for the asset cache's tests (tests/assets, and
// tests/labs, where lab 11's assetsToReload() is the dispatch): a note is a
// text file that may name another file it includes.

#include <stoa/assets/AssetCache.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

namespace stoa::test {

struct Note {
    std::string text;
};

/// A note is its file's text; a first line "include NAME" adds the text of
/// NAME (next to it). A line "broken" is bad input, reported at its line.
inline AssetLoader<Note> noteLoader() {
    return [](const std::filesystem::path& path) {
        LoadedAsset<Note> loaded;
        loaded.files = {path};
        std::string text = readInputFile(path, 1 << 20, "a note");
        if (text.rfind("include ", 0) == 0) {
            const std::filesystem::path included = path.parent_path() / text.substr(8, text.find('\n') - 8);
            loaded.files.push_back(included);
            text = readInputFile(included, 1 << 20, "a note") + text.substr(text.find('\n') + 1);
        }
        const auto broken = text.find("broken");
        if (broken != std::string::npos) {
            const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + broken, '\n'));
            throw InputError(path.string(), line, "a note cannot be broken");
        }
        loaded.asset = std::make_shared<const Note>(Note{text});
        return loaded;
    };
}

/// Calls update() with a time that goes up by `step` each call (and sleeps
/// 20 ms between calls, to let the file system report) until `done()` or 2 s
/// of wall time pass. Returns whether `done()`.
template <typename Done>
inline bool updateUntil(AssetCache& cache, double& now, double step, Done done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    for (;;) {
        now += step;
        cache.update(now);
        if (done()) return true;
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

} // namespace stoa::test
