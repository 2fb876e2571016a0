// editor_benchmark [--runs R]: what stoa-editor's interactivity costs, with the
// solutions' lab 11 code, on one machine, medians of R runs (default 7).
//
// Without OpenGL:
//   - EditHistory: 100,000 mouse moves of one drag merged into one edit, then
//     undone; 10,000 separate edits performed, all undone, all redone
//     (nanoseconds per call);
//   - assetsToReload(): 1,000 assets of 3 files each against 5,000 changes
//     (milliseconds per call);
//   - scene files: a scene of 255 and of 10,000 objects written to JSON text
//     and read back, and saved to and loaded from a file (milliseconds).
// With the headless context ($STOA_HEADLESS picks it), at 1280x720:
//   - a frame of the example scene with 250 more objects (255 in all, the
//     stencil pick's limit): the shaded pass, the selection's outline and gizmo;
//   - the same frame after a click: the stencil pick pass, its read-back and
//     objectAtPixel() on top (the difference is the pick's cost);
//   - the same scene drawn by the deferred pipeline (stoa/render/CourseRenderer.hpp:
//     culling, three shadow cascades, the G-buffer, tiled lights, the sun, the
//     sky), without and with ambient occlusion (lab 09, 32 samples).
// The showcase's frame, pass by pass, is showcase_benchmark's.

#include "BenchmarkTiming.hpp"

#include "editor_app.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/editor/EditorSceneFile.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using stoa::benchmark::Clock;
using stoa::benchmark::median;
using stoa::benchmark::milliseconds;
using namespace stoa;

/// The median over `runs` of how long `work` takes, in milliseconds.
double timed(int runs, const std::function<void()>& work) {
    std::vector<double> times;
    for (int run = 0; run < runs; ++run) {
        const Clock::time_point start = Clock::now();
        work();
        times.push_back(milliseconds(start, Clock::now()));
    }
    return median(times);
}

/// The example scene with objects added in a grid until it holds `count`.
EditorScene sceneWith(std::size_t count) {
    EditorScene scene = loadEditorScene(paths::assetsDir() / "scenes" / "example.json");
    const char* meshes[] = {"shape:cube", "shape:sphere", "shape:cylinder"};
    for (std::size_t i = 0; scene.objects.size() < count; ++i) {
        EditorObject& object = scene.addObject("piece " + std::to_string(i), meshes[i % 3],
                                               scene.materials[i % scene.materials.size()].name);
        object.position = glm::vec3(-9.0f + 1.2f * static_cast<float>(i % 16), 0.5f, -9.0f + 1.2f * static_cast<float>(i / 16 % 16));
        object.scale = glm::vec3(0.6f);
    }
    return scene;
}

void historyFigures(int runs) {
    EditorScene scene;
    scene.addObject("box", "shape:cube", "");
    const std::uint32_t id = scene.objects[0].id;
    const auto move = [id](float x) {
        return EditCommand{"move box", [id, x](EditorScene& s) { s.findObject(id)->position.x = x; },
                           [id](EditorScene& s) { s.findObject(id)->position.x = 0.0f; }, "move box"};
    };
    constexpr int kMoves = 100000;
    const double merged = timed(runs, [&] {
        EditHistory history;
        for (int i = 0; i < kMoves; ++i) history.perform(scene, move(static_cast<float>(i)));
        history.endMerge();
        history.undo(scene);
        if (history.undoCount() != 0 || history.redoCount() != 1) std::abort();
    });
    constexpr int kEdits = 10000;
    const double separate = timed(runs, [&] {
        EditHistory history;
        for (int i = 0; i < kEdits; ++i) {
            history.perform(scene, move(static_cast<float>(i)));
            history.endMerge();
        }
        while (history.undo(scene)) {}
        while (history.redo(scene)) {}
        if (history.undoCount() != static_cast<std::size_t>(kEdits)) std::abort();
    });
    std::printf("EditHistory (your history.cpp):\n");
    std::printf("  %d moves of one drag merged, then undone: %.0f ns per move\n", kMoves, merged * 1e6 / kMoves);
    std::printf("  %d edits performed, undone, redone: %.0f ns per call\n", kEdits, separate * 1e6 / (3.0 * kEdits));
}

void reloadFigures(int runs) {
    std::vector<AssetFiles> assets;
    for (int i = 0; i < 1000; ++i)
        assets.push_back({"asset" + std::to_string(i),
                          {"/a/" + std::to_string(i) + ".png", "/a/" + std::to_string(i) + ".frag", "/a/common.glsl"},
                          1.0});
    std::vector<FileChange> changes;
    for (int i = 0; i < 5000; ++i) changes.push_back({"/a/" + std::to_string(i % 1500) + ".png", 1.0 + 0.001 * i});
    std::size_t due = 0;
    const double time = timed(runs, [&] { due = assetsToReload(changes, assets, 10.0, 0.2).size(); });
    std::printf("assetsToReload (your hot_reload.cpp): 1,000 assets x 5,000 changes: %.2f ms (%zu due)\n", time, due);
}

void fileFigures(int runs) {
    std::printf("scene files (EditorSceneFile):\n");
    char folder[] = "/tmp/stoa-editor-benchmark-XXXXXX";
    if (!mkdtemp(folder)) throw std::runtime_error("cannot make a temporary folder");
    for (const std::size_t count : {std::size_t(255), std::size_t(10000)}) {
        const EditorScene scene = sceneWith(count);
        std::string text;
        const double write = timed(runs, [&] { text = editorSceneToJson(scene); });
        const double read = timed(runs, [&] { (void)editorSceneFromJson(text, "bench.json"); });
        const std::filesystem::path file = std::filesystem::path(folder) / "bench.json";
        const double save = timed(runs, [&] { saveEditorScene(scene, file); });
        const double load = timed(runs, [&] { (void)loadEditorScene(file); });
        std::printf("  %5zu objects (%6.0f kB): to JSON %.2f ms, from JSON %.2f ms, save %.2f ms, load %.2f ms\n", count,
                    static_cast<double>(text.size()) / 1024.0, write, read, save, load);
    }
    std::filesystem::remove_all(folder);
}

void frameFigures(int runs) {
    char folder[] = "/tmp/stoa-editor-benchmark-XXXXXX";
    if (!mkdtemp(folder)) throw std::runtime_error("cannot make a temporary folder");
    const std::filesystem::path sceneFile = std::filesystem::path(folder) / "bench.json";
    const std::filesystem::path deferredFile = std::filesystem::path(folder) / "deferred.json";
    const std::filesystem::path occlusionFile = std::filesystem::path(folder) / "occlusion.json";
    EditorScene scene = sceneWith(255);
    saveEditorScene(scene, sceneFile);
    scene.renderer.deferred = true;
    saveEditorScene(scene, deferredFile);
    scene.renderer.ssao = true;
    saveEditorScene(scene, occlusionFile);
    const std::string camera = "camera = orbit\ntarget = 0 0.5 0\ndistance = 18\nyaw = 30\npitch = 35\nresolution = 1280 720\n";
    const LabManifest manifest = parseManifest(
        "lab = 11_editor\n\n[case frame]\ndescription = d\nscene = " + sceneFile.string() + "\n" + camera +
            "\n[case click]\ndescription = d\nscene = " + sceneFile.string() + "\n" + camera + "commands = select 640 360\n" +
            "\n[case deferred]\ndescription = d\nscene = " + deferredFile.string() + "\n" + camera +
            "\n[case occlusion]\ndescription = d\nscene = " + occlusionFile.string() + "\n" + camera,
        "editor_benchmark");

    HeadlessContext context;
    std::printf("frames (headless, %s), 1280x720, the example scene with 250 more objects:\n", context.description().c_str());
    LabResources resources({STOA_SOLUTIONS_DIR, paths::shadersDir()});   // as a solutions build's lab 11 finds its GLSL
    const glm::ivec2 size(1280, 720);
    const Framebuffer target(size.x, size.y);
    target.bind();
    EditorLabApp app;
    app.initialize(resources);
    const auto frame = [&](const char* name) {
        app.loadCase(*manifest.find(name));
        app.render(size);
        glFinish();
    };
    const char* names[] = {"frame", "click", "deferred", "occlusion"};
    for (const char* name : names) frame(name);   // warm-up: shaders, textures
    std::vector<double> times[4];
    for (int run = 0; run < runs; ++run)   // interleaved
        for (int i = 0; i < 4; ++i) {
            const Clock::time_point start = Clock::now();
            frame(names[i]);
            times[i].push_back(milliseconds(start, Clock::now()));
        }
    const double plain = median(times[0]), clicked = median(times[1]);
    std::printf("  a frame (scene file loaded, drawn forward): %.1f ms\n", plain);
    std::printf("  a frame with a click (pick pass, read-back, objectAtPixel): %.1f ms, the pick %.1f ms of it\n", clicked,
                clicked - plain);
    std::printf("  the deferred pipeline (cascaded shadows, tiled lights, sky): %.1f ms; with ambient occlusion: %.1f ms\n", median(times[2]),
                median(times[3]));
    std::filesystem::remove_all(folder);
}

} // namespace

int main(int argc, char** argv) {
    int runs = 7;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = std::atoi(argv[++i]);
            if (runs < 1 || runs > 1000) {
                std::fprintf(stderr, "editor_benchmark: --runs takes 1 to 1000\n");
                return 2;
            }
        } else {
            std::fprintf(stderr, "usage: editor_benchmark [--runs R]\n");
            return 2;
        }
    }
    try {
        std::printf("editor_benchmark: medians of %d runs\n", runs);
        historyFigures(runs);
        reloadFigures(runs);
        fileFigures(runs);
        frameFigures(runs);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "editor_benchmark: %s\n", error.what());
        return 1;
    }
    return 0;
}
