// Replays the loaders' regression corpus through the fuzzers' entry points,
// in a normal (gcc) build: CTest runs it in every build, and the sanitizer
// stage of .ci/test-all.sh runs it under ASan and UBSan, so no clang is needed.
//
//   stoa-fuzz-replay CORPUS_DIR [MORE_DIRS...]
//
// CORPUS_DIR is what make-regression-corpus.py writes: regression/{obj,image,md2,crowd_xml,editor_scene,sound}
// and seeds/{obj,image,md2,crowd_xml,editor_scene,sound}; a further folder (tests/fuzz/findings) holds
// obj/, image/ and md2/ too; the folder picks the entry point. A file named
// "ok-..." and every seed must load, a file named "err-..." must be refused
// with an InputError (an image as an image and as a height map); any other
// name only must not crash.

#include "FuzzTargets.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

int failures = 0;
int files = 0;

void expect(bool condition, const fs::path& path, const char* what) {
    if (condition) return;
    std::fprintf(stderr, "FAILED: %s: %s\n", path.string().c_str(), what);
    ++failures;
}

void replay(const fs::path& folder, bool seeds) {
    for (const char* kind : {"obj", "image", "md2", "crowd_xml", "editor_scene", "sound"}) {
        const fs::path dir = folder / kind;
        if (!fs::is_directory(dir)) continue;
        std::vector<fs::path> paths;
        for (const auto& entry : fs::directory_iterator(dir)) {
            if (entry.is_regular_file()) paths.push_back(entry.path());
        }
        std::sort(paths.begin(), paths.end());
        for (const fs::path& path : paths) {
            const std::string bytes = readAll(path);
            const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
            const std::string name = path.filename().string();
            const bool mustLoad = seeds || name.rfind("ok-", 0) == 0;
            const bool mustFail = name.rfind("err-", 0) == 0;
            ++files;
            if (std::string(kind) == "obj" || std::string(kind) == "md2") {
                const bool loaded = std::string(kind) == "obj" ? stoa::fuzz::obj(data, bytes.size())
                                                               : stoa::fuzz::md2(data, bytes.size());
                if (mustLoad) expect(loaded, path, "must load, but was refused");
                if (mustFail) expect(!loaded, path, "must be refused, but loaded");
            } else if (std::string(kind) == "sound") {
                const bool loaded = stoa::fuzz::sound(data, bytes.size());
                if (mustLoad) expect(loaded, path, "must load, but was refused");
                if (mustFail) expect(!loaded, path, "must be refused, but loaded");
            } else if (std::string(kind) == "crowd_xml" || std::string(kind) == "editor_scene") {
                const bool loaded = std::string(kind) == "crowd_xml" ? stoa::fuzz::crowdXml(data, bytes.size())
                                                                     : stoa::fuzz::editorScene(data, bytes.size());
                if (mustLoad) expect(loaded, path, "must load, but was refused");
                if (mustFail) expect(!loaded, path, "must be refused, but loaded");
            } else {
                const bool loaded = stoa::fuzz::image(data, bytes.size());
                const bool loadedAsHeightMap = stoa::fuzz::heightMap(data, bytes.size());
                if (mustLoad) expect(loaded, path, "must load as an image, but was refused");
                if (mustFail) {
                    expect(!loaded, path, "must be refused as an image, but loaded");
                    expect(!loadedAsHeightMap, path, "must be refused as a height map, but loaded");
                }
            }
        }
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s CORPUS_DIR [MORE_DIRS...]\n", argv[0]);
        return 2;
    }
    replay(fs::path(argv[1]) / "regression", false);
    replay(fs::path(argv[1]) / "seeds", true);
    for (int i = 2; i < argc; ++i) replay(argv[i], false);
    std::printf("replayed %d files, %d failed expectations\n", files, failures);
    if (files == 0) {
        std::fprintf(stderr, "no files found: run make-regression-corpus.py first\n");
        return 1;
    }
    return failures == 0 ? 0 : 1;
}
