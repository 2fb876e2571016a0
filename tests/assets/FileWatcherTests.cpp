#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/assets/FileWatcher.hpp>

#include <chrono>
#include <cstdlib>
#include <thread>

#ifdef __linux__
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>
#endif

using namespace stoa;
namespace fs = std::filesystem;

namespace {

/// Polls `watcher` every 20 ms until it reports a change or `seconds` pass;
/// every change seen on the way, in order.
std::vector<FileChange> pollUntilChange(FileWatcher& watcher, double seconds = 2.0) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
        std::vector<FileChange> changes = watcher.poll();
        if (!changes.empty() || std::chrono::steady_clock::now() > deadline) return changes;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

std::vector<std::string> filesOf(const std::vector<FileChange>& changes) {
    std::vector<std::string> files;
    for (const FileChange& change : changes) files.push_back(change.file);
    return files;
}

/// Sets the environment variable `name` to `value` ("" removes it) while it lives.
class ScopedVariable {
public:
    ScopedVariable(const char* name, const std::string& value) : m_name(name) {
        if (const char* old = std::getenv(name)) m_old = old;
        set(value);
    }
    ~ScopedVariable() { set(m_old); }
    ScopedVariable(const ScopedVariable&) = delete;
    ScopedVariable& operator=(const ScopedVariable&) = delete;

private:
    void set(const std::string& value) {
#ifdef _WIN32
        _putenv_s(m_name, value.c_str()); // "" removes it
#else
        if (value.empty()) unsetenv(m_name);
        else setenv(m_name, value.c_str(), 1);
#endif
    }
    const char* m_name;
    std::string m_old;
};

FileWatcher::Backend backendOf(const std::string& name) {
    return name == "polling" ? FileWatcher::Backend::Polling : FileWatcher::Backend::Automatic;
}

} // namespace

TEST_CASE("FileWatcher: sees a write and a rename over the file, ignores other files in the folder") {
    const std::string backend = GENERATE(as<std::string>{}, "automatic", "polling");
    INFO("backend: " << backend);
    test::TempFolder folder("watcher");
    const fs::path watched = folder.write("shader.frag", "first");
    folder.write("other.frag", "first");

    double clock = 10.0;
    FileWatcher watcher(backendOf(backend), [&clock] { return clock; });
#ifdef __linux__
    CHECK(watcher.usesInotify() == (backend == "automatic"));
#endif
    // Spelt another way: watched under its absolute, lexically normal path.
    watcher.watch(folder.path() / "sub" / ".." / "shader.frag");
    watcher.watch(watched); // again: nothing new
    REQUIRE(watcher.files() == std::vector<std::string>{FileWatcher::normalPath(watched)});
    CHECK(watcher.poll().empty());

    SECTION("a write") {
        folder.write("shader.frag", "second, longer");
        clock = 11.5;
        const std::vector<FileChange> changes = pollUntilChange(watcher);
        REQUIRE(changes.size() == 1);
        CHECK(changes[0].file == FileWatcher::normalPath(watched));
        CHECK(changes[0].seconds == 11.5);
        CHECK(watcher.poll().empty()); // reported once
    }
    SECTION("a temporary file renamed over it, as editors save") {
        const fs::path temporary = folder.write("shader.frag.tmp", "saved by an editor");
        CHECK(watcher.poll().empty()); // the temporary file is not watched
        fs::rename(temporary, watched);
        const std::vector<FileChange> changes = pollUntilChange(watcher);
        CHECK(filesOf(changes) == std::vector<std::string>{FileWatcher::normalPath(watched)});
        // The watch outlives the rename: the next save is seen too.
        folder.write("shader.frag", "saved again");
        CHECK(filesOf(pollUntilChange(watcher)) == std::vector<std::string>{FileWatcher::normalPath(watched)});
    }
    SECTION("other files in the same folder are ignored") {
        folder.write("other.frag", "changed, but nobody watches it");
        folder.write("new.frag", "new");
        fs::rename(folder / "new.frag", folder / "renamed.frag");
        // Then the watched file, so that the wait ends on something.
        folder.write("shader.frag", "second, longer");
        CHECK(filesOf(pollUntilChange(watcher)) == std::vector<std::string>{FileWatcher::normalPath(watched)});
    }
    SECTION("a deleted file is no change; its coming back is") {
        fs::remove(watched);
        CHECK(watcher.poll().empty());
        folder.write("shader.frag", "back again");
        CHECK(filesOf(pollUntilChange(watcher)) == std::vector<std::string>{FileWatcher::normalPath(watched)});
    }
    CHECK(watcher.takeLog().empty());
}

TEST_CASE("FileWatcher: a file in a folder that does not exist yet is seen once the folder appears") {
    const std::string backend = GENERATE(as<std::string>{}, "automatic", "polling");
    INFO("backend: " << backend);
    test::TempFolder folder("watcher-later");
    FileWatcher watcher(backendOf(backend));
    watcher.watch(folder / "later" / "lit.frag");
    CHECK(watcher.poll().empty());
    folder.write("later/lit.frag", "now it exists");
    CHECK(filesOf(pollUntilChange(watcher)) ==
          std::vector<std::string>{FileWatcher::normalPath(folder / "later" / "lit.frag")});
}

TEST_CASE("FileWatcher: several files, each reported once per poll, in the order watched") {
    const std::string backend = GENERATE(as<std::string>{}, "automatic", "polling");
    INFO("backend: " << backend);
    test::TempFolder folder("watcher-many");
    FileWatcher watcher(backendOf(backend));
    const fs::path a = folder.write("a/one.glsl", "1");
    const fs::path b = folder.write("b/two.glsl", "2");
    watcher.watch(b);
    watcher.watch(a);
    folder.write("a/one.glsl", "one");
    folder.write("a/one.glsl", "one again");
    folder.write("b/two.glsl", "two");
    // Both writes are done before the poll: one poll reports both.
    const std::vector<FileChange> changes = pollUntilChange(watcher);
    CHECK(filesOf(changes) == std::vector<std::string>{FileWatcher::normalPath(b), FileWatcher::normalPath(a)});
}

TEST_CASE("FileWatcher: STOA_FILE_WATCHER=polling makes the automatic watcher poll") {
    test::TempFolder folder("watcher-variable");
    const fs::path watched = folder.write("lit.frag", "first");
    {
        ScopedVariable polling("STOA_FILE_WATCHER", "polling");
        FileWatcher watcher;
        CHECK_FALSE(watcher.usesInotify());
        watcher.watch(watched);
        folder.write("lit.frag", "second, longer");
        CHECK(filesOf(pollUntilChange(watcher)) == std::vector<std::string>{FileWatcher::normalPath(watched)});
        CHECK(watcher.takeLog().empty()); // asked for: nothing to report
    }
#ifdef __linux__
    ScopedVariable other("STOA_FILE_WATCHER", "inotify");
    CHECK(FileWatcher().usesInotify());
#endif
}

TEST_CASE("FileWatcher: polling sees a new size at the same time, and a new time at the same size") {
    test::TempFolder folder("watcher-stamps");
    const fs::path watched = folder.write("height.pgm", "12345");
    const fs::file_time_type written = fs::last_write_time(watched);
    FileWatcher watcher(FileWatcher::Backend::Polling);
    watcher.watch(watched);
    CHECK(watcher.poll().empty());

    SECTION("the size changed, the time was set back") {
        folder.write("height.pgm", "1234567");
        fs::last_write_time(watched, written);
        CHECK(filesOf(watcher.poll()) == std::vector<std::string>{FileWatcher::normalPath(watched)});
    }
    SECTION("the same size, a later time") {
        folder.write("height.pgm", "54321");
        fs::last_write_time(watched, written + std::chrono::seconds(2));
        CHECK(filesOf(watcher.poll()) == std::vector<std::string>{FileWatcher::normalPath(watched)});
    }
    SECTION("neither changed: no change, even after a write of the same bytes") {
        folder.write("height.pgm", "12345");
        fs::last_write_time(watched, written);
        CHECK(watcher.poll().empty());
    }
    CHECK(watcher.poll().empty()); // each change once
}

#ifdef __linux__
TEST_CASE("FileWatcher: when inotify cannot start, it polls and says so once") {
    test::TempFolder folder("watcher-no-inotify");
    const fs::path watched = folder.write("lit.frag", "first");
    // No descriptor left for inotify_init1(): the soft limit on open files is
    // set to the lowest free descriptor while the watcher is made.
    const int lowest = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    REQUIRE(lowest >= 0);
    ::close(lowest);
    rlimit limit{};
    REQUIRE(::getrlimit(RLIMIT_NOFILE, &limit) == 0);
    const rlimit restore = limit;
    limit.rlim_cur = static_cast<rlim_t>(lowest);
    REQUIRE(::setrlimit(RLIMIT_NOFILE, &limit) == 0);
    FileWatcher watcher;
    REQUIRE(::setrlimit(RLIMIT_NOFILE, &restore) == 0);

    CHECK_FALSE(watcher.usesInotify());
    const std::vector<std::string> log = watcher.takeLog();
    REQUIRE(log.size() == 1);
    CHECK(log[0].find("FileWatcher: inotify_init1() failed (Too many open files); polling") == 0);
    watcher.watch(watched);
    folder.write("lit.frag", "second, longer");
    CHECK(filesOf(pollUntilChange(watcher)) == std::vector<std::string>{FileWatcher::normalPath(watched)});
    CHECK(watcher.takeLog().empty());
}
#endif
