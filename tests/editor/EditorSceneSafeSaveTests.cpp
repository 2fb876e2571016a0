// Saving a scene file never destroys anything (EditorSceneFile.hpp,
// framework/src/editor/SafeSave.hpp): a read-only file, a FIFO, a device and a
// symbolic link loop are refused and left as they were; a symbolic link is
// written through, so it stays a link; the temporary files of saves killed
// mid-way are removed by the next save or open once their process is gone,
// never while it runs. None of it needs root.

#include "catch.hpp"
#include "EditorSceneFileSamples.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/editor/EditorSceneFile.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace stoa;
using stoa::test::TempFolder;
namespace fs = std::filesystem;

namespace {

using stoa::test::scene_file::contains;
using stoa::test::scene_file::kScene;
using stoa::test::scene_file::readText;


/// The names in `folder`, sorted.
std::vector<std::string> namesIn(const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// The message of the InputError saveEditorScene throws for `file`.
std::string refusal(const fs::path& file) {
    try {
        saveEditorScene(editorSceneFromJson(kScene, "scene.json"), file);
    } catch (const InputError& error) {
        CHECK(error.file() == file.string());
        return error.message();
    }
    FAIL("saved over " << file.string());
    return "";
}

/// The PID of a process that has ended: a child that exits at once, waited for.
pid_t deadPid() {
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) ::_exit(0);
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    REQUIRE((::kill(child, 0) == -1 && errno == ESRCH));
    return child;
}

} // namespace

TEST_CASE("A read-only scene file is refused and left as it was", "[editor][scene-file][safe-save]") {
    TempFolder folder("editor-save");
    const fs::path file = folder.write("level.json", "the old scene\n");
    REQUIRE(::chmod(file.c_str(), 0444) == 0);
    const std::string message = refusal(file);
    CHECK(contains(message, "read-only"));
    CHECK(readText(file) == "the old scene\n");
    struct stat info {};
    REQUIRE(::stat(file.c_str(), &info) == 0);
    CHECK((info.st_mode & 07777) == 0444);
    CHECK(namesIn(folder.path()) == std::vector<std::string>{"level.json"});
}

TEST_CASE("A FIFO in the scene file's place is refused without blocking", "[editor][scene-file][safe-save]") {
    TempFolder folder("editor-save");
    const fs::path fifo = folder / "level.json";
    REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
    // First in a child, so that a save that opened the FIFO and blocked fails
    // this test after 5 s instead of hanging it.
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        try {
            saveEditorScene(EditorScene{}, fifo);
        } catch (const InputError&) {
            ::_exit(0);
        }
        ::_exit(1);
    }
    int status = -1;
    for (int i = 0; i < 500 && ::waitpid(child, &status, WNOHANG) == 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (::waitpid(child, &status, WNOHANG) == 0) {
        ::kill(child, SIGKILL);
        ::waitpid(child, &status, 0);
        FAIL("saving to a FIFO blocked");
    }
    CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
    CHECK(contains(refusal(fifo), "a FIFO (a named pipe), not a regular file"));
    CHECK(fs::is_fifo(fifo));
    CHECK(namesIn(folder.path()) == std::vector<std::string>{"level.json"});
}

TEST_CASE("A device, directly or through a link, is refused and nothing is written",
          "[editor][scene-file][safe-save]") {
    TempFolder folder("editor-save");
    CHECK(contains(refusal("/dev/null"), "it is a character device, not a regular file"));
    CHECK(fs::is_character_file("/dev/null"));
    const fs::path link = folder / "level.json";
    fs::create_symlink("/dev/null", link);
    CHECK(contains(refusal(link), "the link's target /dev/null is a character device"));
    CHECK(fs::read_symlink(link) == "/dev/null");
    CHECK(namesIn(folder.path()) == std::vector<std::string>{"level.json"});
    for (const std::string& name : namesIn("/dev")) CHECK(name.rfind(".null.saving-", 0) != 0);
}

TEST_CASE("A folder in the scene file's place is refused, saying what it is", "[editor][scene-file][safe-save]") {
    TempFolder folder("editor-save");
    fs::create_directories(folder / "level.json");
    CHECK(contains(refusal(folder / "level.json"), "it is a folder, not a regular file"));
    CHECK(fs::is_directory(folder / "level.json"));
}

TEST_CASE("A save through a symbolic link writes the link's target and the link stays a link",
          "[editor][scene-file][safe-save]") {
    TempFolder folder("editor-save");
    const fs::path target = folder.write("real/level.json", "the old scene\n");
    fs::create_symlink("real/level.json", folder / "link.json");   // relative to the link's folder
    fs::create_symlink(folder / "link.json", folder / "chain.json");
    const EditorScene scene = editorSceneFromJson(kScene, "scene.json");
    for (const char* name : {"link.json", "chain.json"}) {
        INFO(name);
        fs::remove(target);
        std::ofstream(target) << "the old scene\n";
        saveEditorScene(scene, folder / name);
        CHECK(readText(target) == editorSceneToJson(scene));
        CHECK(fs::is_symlink(folder / "link.json"));
        CHECK(fs::read_symlink(folder / "link.json") == "real/level.json");
        CHECK(fs::is_symlink(folder / "chain.json"));
        CHECK(namesIn(folder.path()) == std::vector<std::string>{"chain.json", "link.json", "real"});
        CHECK(namesIn(folder / "real") == std::vector<std::string>{"level.json"});
    }
    // A link to a file not yet written: the file is made, the link kept.
    fs::create_symlink("real/new.json", folder / "new.json");
    saveEditorScene(scene, folder / "new.json");
    CHECK(fs::is_symlink(folder / "new.json"));
    CHECK(readText(folder / "real" / "new.json") == editorSceneToJson(scene));
    // A link to a read-only file: refused, naming the target.
    REQUIRE(::chmod(target.c_str(), 0444) == 0);
    const std::string message = refusal(folder / "link.json");
    CHECK(contains(message, "the link's target " + (folder / "real/level.json").string() + " is read-only"));
    CHECK(readText(target) == editorSceneToJson(scene));
}

TEST_CASE("A symbolic link loop is refused and its links kept", "[editor][scene-file][safe-save]") {
    TempFolder folder("editor-save");
    fs::create_symlink("b.json", folder / "a.json");
    fs::create_symlink("a.json", folder / "b.json");
    fs::create_symlink("self.json", folder / "self.json");
    CHECK(contains(refusal(folder / "a.json"), "symbolic link loop"));
    CHECK(contains(refusal(folder / "self.json"), "symbolic link loop"));
    CHECK(fs::read_symlink(folder / "a.json") == "b.json");
    CHECK(fs::read_symlink(folder / "b.json") == "a.json");
    CHECK(fs::read_symlink(folder / "self.json") == "self.json");
    CHECK(namesIn(folder.path()) == std::vector<std::string>{"a.json", "b.json", "self.json"});
}

TEST_CASE("Temporary files of killed saves are removed on save and open, never a running process's",
          "[editor][scene-file][safe-save]") {
    TempFolder folder("editor-save");
    const std::string dead = std::to_string(deadPid());
    const std::string mine = std::to_string(::getpid());
    const fs::path file = folder.write("level.json", kScene);
    // Kept: of running processes (this one, and 1, which always runs), not
    // the pattern, another file's.
    const std::vector<std::string> kept = {".level.json.saving-" + mine + "-3", ".level.json.saving-1-0",
                                           ".level.json.saving-" + dead, ".level.json.saving-" + dead + "-x",
                                           ".other.json.saving-" + dead + "-0"};
    const std::vector<std::string> stale = {".level.json.saving-" + dead + "-0", ".level.json.saving-" + dead + "-17"};
    const auto plant = [&](const std::vector<std::string>& names) {
        for (const std::string& name : names) folder.write(name, "half a scene");
    };
    std::vector<std::string> expected = kept;
    expected.push_back("level.json");
    std::sort(expected.begin(), expected.end());

    plant(kept);
    plant(stale);
    saveEditorScene(editorSceneFromJson(kScene, "scene.json"), file);
    CHECK(namesIn(folder.path()) == expected);

    plant(stale);
    (void)loadEditorScene(file);
    CHECK(namesIn(folder.path()) == expected);

    // Through a link, those beside the link's target.
    fs::create_directories(folder / "links");
    fs::create_symlink("../level.json", folder / "links" / "level.json");
    plant(stale);
    (void)loadEditorScene(folder / "links" / "level.json");
    expected.push_back("links");
    std::sort(expected.begin(), expected.end());
    CHECK(namesIn(folder.path()) == expected);
}
