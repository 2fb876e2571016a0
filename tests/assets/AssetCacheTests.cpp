// The cache's bookkeeping without OpenGL: a made-up kind of asset (a note, a
// text file that may name another file it includes) stands for the real ones.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/assets/AssetCache.hpp>
#include <stoa/assets/DataAssets.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>
#include <stoa/core/Paths.hpp>

#include <algorithm>
#include <chrono>
#include <thread>

using namespace stoa;
namespace fs = std::filesystem;

namespace {

struct Note {
    std::string text;
};

/// A note is its file's text; a first line "include NAME" adds the text of
/// NAME (next to it). A line "broken" is bad input, reported at its line.
AssetLoader<Note> noteLoader() {
    return [](const fs::path& path) {
        LoadedAsset<Note> loaded;
        loaded.files = {path};
        std::string text = readInputFile(path, 1 << 20, "a note");
        if (text.rfind("include ", 0) == 0) {
            const fs::path included = path.parent_path() / text.substr(8, text.find('\n') - 8);
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
bool updateUntil(AssetCache& cache, double& now, double step, Done done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    for (;;) {
        now += step;
        cache.update(now);
        if (done()) return true;
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

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

TEST_CASE("AssetCache: a debounce dispatch reloads once the files have been quiet") {
    const double debounce = 0.5;
    // Lab 11's rule, written here: due when a file changed after the asset was
    // loaded and no file of it changed in the last `debounceSeconds`.
    const ReloadDispatch debounced = [](const std::vector<FileChange>& changes, const std::vector<AssetFiles>& assets,
                                        double now, double debounceSeconds) {
        std::vector<std::string> due;
        for (const AssetFiles& asset : assets) {
            bool changedSinceLoad = false;
            double latest = -1e300;
            for (const FileChange& change : changes) {
                if (std::find(asset.files.begin(), asset.files.end(), change.file) == asset.files.end()) continue;
                changedSinceLoad = changedSinceLoad || change.seconds > asset.loadedAt;
                latest = std::max(latest, change.seconds);
            }
            if (changedSinceLoad && latest <= now - debounceSeconds) due.push_back(asset.name);
        }
        return due;
    };

    test::TempFolder folder("cache-debounce");
    folder.write("a.txt", "include common.txt\nA");
    folder.write("common.txt", "one ");
    folder.write("b.txt", "B");
    AssetCacheOptions options;
    options.debounceSeconds = debounce;
    AssetCache cache(folder.path(), options);
    cache.setLoader<Note>(noteLoader());
    int calls = 0;
    cache.setReloadDispatch([&](const std::vector<FileChange>& changes, const std::vector<AssetFiles>& assets,
                                double now, double debounceSeconds) {
        ++calls;
        CHECK(debounceSeconds == debounce);
        return debounced(changes, assets, now, debounceSeconds);
    });
    AssetRef<Note> a = cache.get<Note>("a.txt");
    AssetRef<Note> b = cache.get<Note>("b.txt");
    CHECK(a->text == "one A");
    REQUIRE(cache.assets().size() == 2);
    CHECK(cache.assets()[0].files.size() == 2); // a.txt and the file it includes

    double now = 1.0;
    cache.update(now);
    CHECK(calls == 0); // no change: nothing to ask

    // A burst of saves of the included file: no reload while it goes on.
    folder.write("common.txt", "two ");
    REQUIRE(updateUntil(cache, now, 0.01, [&] { return !cache.pendingChanges().empty(); }));
    const double firstSave = now;
    CHECK(calls == 1);
    cache.update(firstSave + 0.3);
    now = firstSave + 0.3;
    folder.write("common.txt", "three ");
    REQUIRE(updateUntil(cache, now, 0.01, [&] { return cache.pendingChanges().back().seconds > firstSave; }));
    const double lastSave = now;
    CHECK(a.version() == 1);
    cache.update(lastSave + debounce - 0.01);
    CHECK(a.version() == 1); // still within the debounce of the last save

    cache.update(lastSave + debounce + 0.001);
    CHECK(a.version() == 2); // quiet long enough: one reload for the whole burst
    CHECK(a->text == "three A");
    CHECK(b.version() == 1); // another asset, untouched
    CHECK(cache.takeLog() == std::vector<std::string>{"reloaded a.txt"});
    CHECK(cache.pendingChanges().empty());
    cache.update(lastSave + 2 * debounce);
    CHECK(a.version() == 2);
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
