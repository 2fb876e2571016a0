// The asset cache (framework/include/stoa/assets/AssetCache.hpp) with lab 11's
// assetsToReload() as its dispatch: a burst of saves reloads once, after the
// files were quiet for the debounce. Here, not in tests/assets, because it
// links the solution (the student release leaves tests/labs out).

#include "catch.hpp"
#include "TempFolder.hpp"
#include "NoteAsset.hpp"

#include "lab11.hpp"

using namespace stoa;
using stoa::test::Note;
using stoa::test::noteLoader;
using stoa::test::updateUntil;

TEST_CASE("Lab 11 (editor): the asset cache with assetsToReload() reloads once the files have been quiet") {
    const double debounce = 0.5;

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
        return assetsToReload(changes, assets, now, debounceSeconds);   // lab 11's
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

