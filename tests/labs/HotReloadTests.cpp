// Lab 11's hot reload decision (labs/11_editor/student/lab11.hpp) on cases
// written here:
//   - assetsToReload on a table of scenarios: the debounce boundary (a change
//     exactly debounce seconds ago counts as quiet), changes at or before
//     loadedAt ignored, files no asset uses ignored, every file of an asset
//     counts, the order of `assets` kept, each asset once however many changes;
//     then as the editor's clock ticks.
// The planted mistakes of solutions/11_editor/mistakes/ for it each fail cases
// here (checked by applying each one's find/replace to a copy of the solutions):
//   no_debounce                assetsToReload "table of scenarios", "the clock ticks"
//   first_file_only            assetsToReload "table of scenarios", "the clock ticks"
// AssetReloadTests.cpp tests it as the asset cache's dispatch; StencilPickTests.cpp,
// GizmoTests.cpp and HistoryTests.cpp test the rest of the lab's editor core.

#include "catch.hpp"

#include "lab11.hpp"

#include <string>
#include <vector>

using namespace stoa;

// --- assetsToReload -----------------------------------------------------------------------

TEST_CASE("Lab 11: assetsToReload on a table of scenarios", "[lab11][editor]") {
    const std::string diffuse = "/assets/panel_diffuse.png", stripes = "/assets/panel_stripes.png";
    const std::string shader = "/shaders/lit.frag", common = "/shaders/common.glsl", other = "/assets/unrelated.png";
    struct Scenario {
        const char* name;
        std::vector<FileChange> changes;
        std::vector<AssetFiles> assets;
        double now, debounce;
        std::vector<std::string> expected;
    };
    const AssetFiles panel{"panel", {diffuse, stripes}, 0.0};
    const AssetFiles lit{"lit", {shader, common}, 0.0};
    const std::vector<Scenario> scenarios = {
        {"nothing changed", {}, {panel, lit}, 10.0, 0.25, {}},
        {"one change, quiet since", {{diffuse, 1.0}}, {panel}, 2.0, 0.25, {"panel"}},
        {"one change, not yet quiet", {{diffuse, 1.0}}, {panel}, 1.1, 0.25, {}},
        // The debounce boundary: a change exactly debounce seconds ago counts as quiet
        // (latest <= now - debounce); the values are exact in binary.
        {"debounce: exactly quiet", {{diffuse, 1.0}}, {panel}, 1.25, 0.25, {"panel"}},
        {"debounce: just short of quiet", {{diffuse, 1.0}}, {panel}, 1.2499, 0.25, {}},
        {"debounce 0: due at once", {{diffuse, 1.0}}, {panel}, 1.0, 0.0, {"panel"}},
        {"debounce: the latest change of any file counts", {{diffuse, 1.0}, {stripes, 1.5}}, {panel}, 1.6, 0.25, {}},
        {"debounce: an old change of the asset, a later one of an unrelated file", {{diffuse, 1.0}, {other, 1.9}},
         {panel}, 2.0, 0.25, {"panel"}},
        {"changed before it was loaded", {{diffuse, 1.0}}, {{"panel", {diffuse, stripes}, 2.0}}, 5.0, 0.25, {}},
        {"changed exactly when it was loaded", {{diffuse, 2.0}}, {{"panel", {diffuse, stripes}, 2.0}}, 5.0, 0.25, {}},
        {"changed before and after it was loaded", {{diffuse, 1.0}, {stripes, 3.0}},
         {{"panel", {diffuse, stripes}, 2.0}}, 5.0, 0.25, {"panel"}},
        {"a change before loading keeps it from being quiet", {{diffuse, 3.0}, {stripes, 4.9}},
         {{"panel", {diffuse, stripes}, 3.5}}, 5.0, 0.25, {}},
        {"every file of an asset counts: the second", {{stripes, 1.0}}, {panel}, 2.0, 0.25, {"panel"}},
        {"every file of an asset counts: the last of three", {{"/c", 1.0}}, {{"three", {"/a", "/b", "/c"}, 0.0}}, 2.0,
         0.25, {"three"}},
        {"unrelated files ignored", {{other, 1.0}, {"/assets/panel_diffuse.png.tmp", 1.0}}, {panel, lit}, 5.0, 0.25, {}},
        {"the order of assets kept", {{shader, 1.0}, {diffuse, 1.2}}, {panel, lit}, 5.0, 0.25, {"panel", "lit"}},
        {"the order of assets kept, the other way", {{diffuse, 1.0}, {shader, 1.2}}, {lit, panel}, 5.0, 0.25,
         {"lit", "panel"}},
        {"each once, however many changes",
         {{diffuse, 1.0}, {diffuse, 1.01}, {stripes, 1.02}, {diffuse, 1.03}, {stripes, 1.04}, {diffuse, 1.05}},
         {panel},
         5.0,
         0.25,
         {"panel"}},
        {"a file two assets share reloads both", {{common, 1.0}},
         {{"lit", {shader, common}, 0.0}, {"unlit", {"/shaders/unlit.frag", common}, 0.0}, panel}, 5.0, 0.25,
         {"lit", "unlit"}},
        {"one due, one still busy", {{diffuse, 1.0}, {shader, 4.9}}, {panel, lit}, 5.0, 0.25, {"panel"}},
        {"an asset without files", {{diffuse, 1.0}}, {{"empty", {}, 0.0}, panel}, 5.0, 0.25, {"panel"}},
        {"no assets", {{diffuse, 1.0}}, {}, 5.0, 0.25, {}},
    };
    for (const Scenario& scenario : scenarios) {
        INFO(scenario.name);
        CHECK(assetsToReload(scenario.changes, scenario.assets, scenario.now, scenario.debounce) == scenario.expected);
    }
}

TEST_CASE("Lab 11: assetsToReload as the editor's clock ticks: due once quiet, then not again until a new change",
          "[lab11][editor]") {
    // The case reload_when_quiet: saves at 0, 0.2 and 0.6 s, ticks at 0.1 .. 0.7 s.
    const std::string diffuse = "/lab11/panel_diffuse.png", stripes = "/lab11/panel_stripes.png";
    std::vector<FileChange> changes;
    AssetFiles panel{"panel", {diffuse, stripes}, -1.0};
    std::vector<double> reloads;
    const auto tick = [&](double now) {
        const std::vector<std::string> due = assetsToReload(changes, {panel}, now, 0.25);
        if (!due.empty()) {
            CHECK(due == std::vector<std::string>{"panel"});
            panel.loadedAt = now;
            reloads.push_back(now);
        }
    };
    changes.push_back({diffuse, 0.0});
    tick(0.1);
    changes.push_back({stripes, 0.2});
    tick(0.3);
    tick(0.5);
    tick(0.55);   // loaded at 0.5, nothing changed since
    changes.push_back({diffuse, 0.6});
    tick(0.7);
    tick(0.85);
    tick(0.9);
    CHECK(reloads == std::vector<double>{0.5, 0.85});
}
