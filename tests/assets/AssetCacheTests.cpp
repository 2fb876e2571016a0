// The cache's bookkeeping without OpenGL: a made-up kind of asset (a note, a
// text file that may name another file it includes) stands for the real ones.

#include "catch.hpp"
#include "TempFolder.hpp"
#include "NoteAsset.hpp"

#include <stoa/assets/AssetCache.hpp>
#include <stoa/assets/DataAssets.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>
#include <stoa/core/Paths.hpp>

#include <algorithm>
#include <chrono>
#include <thread>

using namespace stoa;
using stoa::test::Note;
using stoa::test::noteLoader;
using stoa::test::updateUntil;
namespace fs = std::filesystem;

namespace {

bool contains(const std::vector<std::string>& lines, const std::string& part) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const std::string& line) { return line.find(part) != std::string::npos; });
}

std::string describe(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
}

} // namespace

TEST_CASE("AssetCache: an asset is loaded once by name and reloaded when its file changes") {
    test::TempFolder folder("cache-notes");
    folder.write("notes/a.txt", "first");
    AssetCache cache(folder.path());
    cache.setLoader<Note>(noteLoader());

    AssetRef<Note> note = cache.get<Note>("notes/a.txt");
    CHECK(note->text == "first");
    CHECK(note.version() == 1);
    CHECK(note.name() == "notes/a.txt");
    CHECK(cache.get<Note>("notes/a.txt").current() == note.current()); // the same, not loaded again
    const std::shared_ptr<const Note> held = note.current();

    double now = 1.0;
    cache.update(now);
    CHECK(note.version() == 1);
    CHECK(cache.takeLog().empty());

    folder.write("notes/a.txt", "second");
    REQUIRE(updateUntil(cache, now, 0.01, [&] { return note.version() == 2; }));
    CHECK(note->text == "second");
    CHECK(held->text == "first"); // a version someone holds stays alive
    CHECK(cache.takeLog() == std::vector<std::string>{"reloaded notes/a.txt"});
    CHECK(cache.assets()[0].loadedAt == now);
    CHECK(cache.pendingChanges().empty());
}

TEST_CASE("AssetCache: a broken reload keeps the last good version and logs the file and line") {
    test::TempFolder folder("cache-broken");
    const fs::path file = folder.write("a.txt", "good");
    AssetCache cache(folder.path());
    cache.setLoader<Note>(noteLoader());
    AssetRef<Note> note = cache.get<Note>("a.txt");

    double now = 1.0;
    folder.write("a.txt", "fine\nstill fine\nbroken here\n");
    REQUIRE(updateUntil(cache, now, 0.01, [&] { return !cache.errorOf("a.txt").empty(); }));
    CHECK(note.version() == 1);
    CHECK(note->text == "good");
    const std::vector<std::string> log = cache.takeLog();
    INFO(describe(log));
    REQUIRE(log.size() == 1);
    CHECK(contains(log, "cannot reload a.txt, keeping the last good version"));
    CHECK(contains(log, file.string() + ":3: a note cannot be broken"));
    CHECK(cache.errorOf("a.txt").find(file.string() + ":3:") != std::string::npos);

    // Not tried again until the file changes.
    cache.update(now + 1.0);
    now += 1.0;
    CHECK(cache.takeLog().empty());

    folder.write("a.txt", "mended");
    REQUIRE(updateUntil(cache, now, 0.01, [&] { return note.version() == 2; }));
    CHECK(note->text == "mended");
    CHECK(cache.errorOf("a.txt").empty());
    CHECK(cache.takeLog() == std::vector<std::string>{"reloaded a.txt"});
}

TEST_CASE("AssetCache: the first load's error is thrown and nothing is cached") {
    test::TempFolder folder("cache-first");
    folder.write("bad.txt", "broken");
    AssetCache cache(folder.path());
    cache.setLoader<Note>(noteLoader());
    CHECK_THROWS_AS(cache.get<Note>("bad.txt"), InputError);
    CHECK_THROWS_AS(cache.get<Note>("missing.txt"), InputError);
    CHECK_FALSE(cache.contains("bad.txt"));
    CHECK(cache.assets().empty());
}

TEST_CASE("AssetCache: without a dispatch, every asset with a file changed after its load is due") {
    const std::vector<AssetFiles> assets = {
        {"a", {"/x/a.txt", "/x/common.txt"}, 1.0},
        {"b", {"/x/b.txt"}, 3.0},
        {"c", {"/x/common.txt"}, 5.0},
    };
    CHECK(AssetCache::changedSinceLoaded({}, assets).empty());
    CHECK(AssetCache::changedSinceLoaded({{"/x/common.txt", 4.0}}, assets) == std::vector<std::string>{"a"});
    CHECK(AssetCache::changedSinceLoaded({{"/x/b.txt", 3.0}}, assets).empty()); // not later than its load
    CHECK(AssetCache::changedSinceLoaded({{"/x/common.txt", 6.0}, {"/x/b.txt", 3.5}, {"/x/other", 9.0}}, assets) ==
          std::vector<std::string>{"a", "b", "c"});
}

TEST_CASE("AssetCache: a dispatch that names an unknown asset, or one twice, is logged and loads once") {
    test::TempFolder folder("cache-dispatch");
    folder.write("a.txt", "one");
    AssetCache cache(folder.path());
    cache.setLoader<Note>(noteLoader());
    cache.setReloadDispatch([](const std::vector<FileChange>&, const std::vector<AssetFiles>&, double, double) {
        return std::vector<std::string>{"a.txt", "nothing.txt", "a.txt"};
    });
    AssetRef<Note> note = cache.get<Note>("a.txt");
    double now = 1.0;
    folder.write("a.txt", "two");
    REQUIRE(updateUntil(cache, now, 0.01, [&] { return note.version() > 1; }));
    CHECK(note.version() == 2);
    CHECK(cache.takeLog() == std::vector<std::string>{
                                 "reloaded a.txt",
                                 "the reload dispatch named 'nothing.txt', which is not in the cache; ignored"});
}

TEST_CASE("AssetCache: a crowd world's files are the world, its includes and its ground maps") {
    AssetCache cache(paths::assetsDir());
    addDataAssetLoaders(cache);
    AssetRef<CrowdWorld> world = cache.get<CrowdWorld>("crowds/mars_explorers.xml");
    CHECK_FALSE(world->types.empty());
    const std::vector<std::string> files = cache.assets().at(0).files;
    const auto has = [&](const char* name) {
        return std::find(files.begin(), files.end(), FileWatcher::normalPath(paths::assetsDir() / "crowds" / name)) !=
               files.end();
    };
    CHECK(files.size() == 3);
    CHECK(has("mars_explorers.xml"));
    CHECK(has("explorers.xml"));
    CHECK(has("acropolis_collision.png"));

    AssetRef<Md2Model> explorer = cache.get<Md2Model>("crowds/explorer.md2");
    CHECK(explorer->frames.size() > 1);
    CHECK(cache.assets().at(1).files == std::vector<std::string>{FileWatcher::normalPath(
                                            paths::assetsDir() / "crowds" / "explorer.md2")});
}
