// The platform layer (framework/src/platform/) as every platform must show it:
// built into stoa-tests-core on Linux, and run under Wine by
// build-core-mingw.sh, where the Windows code paths answer. The POSIX-only
// cases (FIFOs, /dev/zero, fork) are in ImageHardeningTests.cpp,
// ObjLoaderHardeningTests.cpp and EditorSceneSafeSaveTests.cpp.
#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>
#include <stoa/editor/EditorSceneFile.hpp>
#include <stoa/platform/SaveFiles.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace stoa;
using stoa::test::TempFolder;
namespace fs = std::filesystem;

namespace {

// A process id no system gives out: Linux's pid_max is at most 2^22, and
// Windows answers "no such process" for an id this large.
constexpr platform::ProcessId kEndedProcess = 2147483644;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The message of the InputError `action` throws, naming `file`.
template <typename Action> std::string refusal(const fs::path& file, Action action) {
    try {
        action();
    } catch (const InputError& error) {
        CHECK(error.file() == file.string());
        return error.message();
    }
    FAIL("no InputError for " << file.string());
    return "";
}

std::vector<std::string> namesIn(const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

const std::string kScene = R"({"stoa_scene": 1})";

} // namespace

TEST_CASE("Platform: readInputFile reads a regular file and refuses the rest by name", "[platform]") {
    TempFolder folder("platform-read");
    const fs::path file = folder.write("model.obj", "v 0 0 0\n");
    CHECK(readInputFile(file, 1024, "OBJ file") == "v 0 0 0\n");
    CHECK(readInputFile(folder.write("empty.obj", ""), 1024, "OBJ file").empty());

    const fs::path sub = folder / "models";
    fs::create_directories(sub);
    CHECK(refusal(sub, [&] { (void)readInputFile(sub, 1024, "OBJ file"); }) == "this is a folder, not OBJ file");
    const fs::path missing = folder / "missing.obj";
    CHECK(refusal(missing, [&] { (void)readInputFile(missing, 1024, "OBJ file"); }) == "the file does not exist");
    CHECK(contains(refusal(file, [&] { (void)readInputFile(file, 4, "OBJ file"); }),
                   "the file is too large: 8 bytes, past the limit of 4 bytes"));
#ifdef _WIN32
    // Windows' device names, its /dev/zero and terminal: never opened (Wine says they do not exist).
    CHECK_THROWS_AS(readInputFile("CON", 1024, "OBJ file"), InputError);
    CHECK_THROWS_AS(readInputFile("NUL", 1024, "OBJ file"), InputError);
#endif
}

TEST_CASE("Platform: whether a process runs", "[platform]") {
    CHECK(platform::currentProcessId() > 0);
    CHECK_FALSE(platform::processHasEnded(platform::currentProcessId()));
    CHECK(platform::processHasEnded(kEndedProcess));
    CHECK_FALSE(platform::processHasEnded(0)); // not a process: nothing is known
}

TEST_CASE("Platform: a new file is only made where none is, and replaces another in one step", "[platform]") {
    TempFolder folder("platform-files");
    const fs::path target = folder.write("scene.json", "old");
    const fs::path fresh = folder / ".scene.json.new";
    CHECK(platform::writeNewFile(target, "never written", target) == std::errc::file_exists);
    CHECK(readText(target) == "old");
    REQUIRE_FALSE(platform::writeNewFile(fresh, "new", target));
    CHECK(readText(fresh) == "new");
    REQUIRE_FALSE(platform::replaceFile(fresh, target));
    CHECK(readText(target) == "new");
    CHECK(namesIn(folder.path()) == std::vector<std::string>{"scene.json"});

    const fs::path nowhere = folder / "no-such-folder" / "scene.json";
    const std::error_code error = platform::writeNewFile(nowhere, "text", nowhere);
    REQUIRE(error);
    CHECK(contains(platform::describeWriteError(error, nowhere.parent_path()), "does not exist"));
}

TEST_CASE("Platform: saving a scene replaces the file and leaves no temporary file", "[platform][safe-save]") {
    TempFolder folder("platform-save");
    const fs::path file = folder.write("level.json", "old contents");
    saveEditorScene(editorSceneFromJson(kScene, "scene.json"), file);
    CHECK(contains(readText(file), "\"stoa_scene\""));
    CHECK(namesIn(folder.path()) == std::vector<std::string>{"level.json"});

    SECTION("a read-only file is refused and left as it was") {
        fs::permissions(file, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                        fs::perm_options::remove);
        const std::string before = readText(file);
        CHECK(contains(refusal(file, [&] { saveEditorScene(editorSceneFromJson(kScene, "s"), file); }),
                       "cannot save the scene: it is read-only"));
        CHECK(readText(file) == before);
        fs::permissions(file, fs::perms::owner_write, fs::perm_options::add); // so that it can be removed
    }
    SECTION("a folder is refused") {
        const fs::path sub = folder / "sub.json";
        fs::create_directories(sub);
        CHECK(contains(refusal(sub, [&] { saveEditorScene(editorSceneFromJson(kScene, "s"), sub); }),
                       "it is a folder, not a regular file"));
    }
    SECTION("a folder that does not exist is named") {
        const fs::path nowhere = folder / "missing" / "level.json";
        CHECK(contains(refusal(nowhere, [&] { saveEditorScene(editorSceneFromJson(kScene, "s"), nowhere); }),
                       "does not exist"));
    }
    CHECK(namesIn(folder.path()).size() <= 2); // level.json, and the section's folder
}

TEST_CASE("Platform: a save's temporary file goes once its process has ended", "[platform][safe-save]") {
    TempFolder folder("platform-stale");
    const fs::path file = folder / "level.json";
    saveEditorScene(editorSceneFromJson(kScene, "scene.json"), file);
    const std::string ended = ".level.json.saving-" + std::to_string(kEndedProcess) + "-0";
    const std::string ours = ".level.json.saving-" + std::to_string(platform::currentProcessId()) + "-7";
    folder.write(ended, "left by a save that was killed");
    folder.write(ours, "a save of this process, still running");
    folder.write(".other.json.saving-" + std::to_string(kEndedProcess) + "-0", "another file's");

    (void)loadEditorScene(file);
    const std::vector<std::string> names = namesIn(folder.path());
    CHECK(std::find(names.begin(), names.end(), ended) == names.end());
    CHECK(std::find(names.begin(), names.end(), ours) != names.end());
    CHECK(names.size() == 3); // level.json, ours and the other file's
}
