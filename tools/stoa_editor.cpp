// stoa-editor: a scene file in the scene editor's window, with lab 11's app
// and the code of the track it was built from (yours, in your build): click to
// select, drag the gizmo's arrows, undo and redo, edit in the panels (F1),
// edit the material's shader live, save with Ctrl+S; textures, models and
// shaders reload when another program saves them.
//
//   stoa-editor SCENE.json                    edit it in a window
//   stoa-editor SCENE.json --screenshot FILE  the window's first frame saved as PNG, quit
//   stoa-editor SCENE.json --render FILE [--backend osmesa|egl]
//                                             the same picture headless
//   stoa-editor --scene showcase              a scene of assets/scenes/ by name: the
//                                             showcase has every lab on (docs/showcase.md)
//   ... --size 1280x720                       the picture's size (--render, --screenshot);
//                                             the window opens at 960 x 640
// A scene named without a folder is looked up in assets/scenes/ too, so
// `stoa-editor example.json` opens the example. docs/scene-files.md is the format.

#include "editor_app.hpp"

#include <stoa/editor/EditorSceneFile.hpp>
#include <stoa/lab/LabApp.hpp>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace {

// The usage: asked for (--help, problem empty) on stdout, exit 0; after a
// problem on stderr, exit 2.
int usage(const std::string& problem) {
    if (!problem.empty()) std::fprintf(stderr, "stoa-editor: %s\n", problem.c_str());
    std::fprintf(problem.empty() ? stdout : stderr,
                 "usage: stoa-editor SCENE.json [--size WxH] [--screenshot FILE | --render FILE [--backend osmesa|egl]]\n"
                 "       stoa-editor --scene NAME ...   (a scene of assets/scenes/ by its name; --scene showcase: every lab at once)\n"
                 "Edits a scene file (docs/scene-files.md) in a window, or saves one picture of it.\n");
    return problem.empty() ? 0 : 2;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    std::error_code error;
    if (!args.empty() && args[0] == "--scene") {   // a scene of assets/scenes/ by its name
        if (args.size() < 2 || args[1].empty() || args[1][0] == '-') return usage("--scene needs a name, e.g. --scene showcase");
        std::filesystem::path named = stoa::paths::assetsDir() / "scenes" / args[1];
        if (named.extension() != ".json") named += ".json";
        if (!std::filesystem::is_regular_file(named, error))
            return usage("no scene called " + args[1] + " in " + (stoa::paths::assetsDir() / "scenes").string());
        args.erase(args.begin());
        args[0] = named.string();
    }
    if (args.empty() || args[0].empty() || args[0][0] == '-')
        return usage(!args.empty() && (args[0] == "--help" || args[0] == "-h")
                         ? ""
                         : args.empty() ? "the first argument is the scene file (none given)"
                                        : "the first argument is the scene file");
    std::filesystem::path scene = args[0];
    if (!std::filesystem::exists(scene, error) && scene.parent_path().empty())
        scene = stoa::paths::assetsDir() / "scenes" / scene;
    if (!std::filesystem::is_regular_file(scene, error)) {
        const std::filesystem::file_status status = std::filesystem::status(scene, error);
        if (!std::filesystem::exists(status)) return usage("no scene file " + args[0]);
        const char* what = std::filesystem::is_directory(status) ? "a folder"
                           : std::filesystem::is_fifo(status)    ? "a FIFO (a named pipe)"
                           : std::filesystem::is_socket(status)  ? "a socket"
                                                                 : "a device";
        return usage(args[0] + " is " + what + ", not a scene file");
    }
    scene = std::filesystem::absolute(scene).lexically_normal();

    std::vector<std::string> forwarded;
    int width = 512, height = 512;   // a case's default
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& flag = args[i];
        const bool hasValue = i + 1 < args.size();
        if (flag == "--size" && hasValue) {
            char x = 0;
            std::istringstream size(args[++i]);
            if (!(size >> width >> x >> height) || x != 'x' || !size.eof() || width < 64 || height < 64 || width > 4096 ||
                height > 4096)
                return usage("--size expects WIDTHxHEIGHT from 64x64 to 4096x4096, e.g. 1280x720; got " + args[i]);
        } else if ((flag == "--screenshot" || flag == "--backend" || flag == "--render") && hasValue) {
            forwarded.push_back(flag);
            forwarded.push_back(args[++i]);
        } else {
            return usage("unknown or incomplete flag " + flag);
        }
    }

    // The scene's camera, read now so the case can start there (a broken file
    // is reported here, with its line, before any window opens).
    stoa::EditorScene loaded;
    try {
        loaded = stoa::loadEditorScene(scene);
    } catch (const std::exception& problem) {
        std::fprintf(stderr, "stoa-editor: %s\n", problem.what());
        return 1;
    }

    // One case for the lab app, at the scene's camera.
    const stoa::EditorCamera& camera = loaded.camera;
    std::ostringstream cases;
    cases << "lab = 11_editor\ntitle = stoa-editor\n\n[case scene]\ndescription = " << scene.filename().string()
          << "\nscene = " << scene.string() << "\ncamera = orbit\ntarget = " << camera.target.x << ' '
          << camera.target.y << ' ' << camera.target.z << "\ndistance = " << camera.distance
          << "\nyaw = " << camera.yawDegrees << "\npitch = " << camera.pitchDegrees << "\nfar = 400\nresolution = " << width << ' '
          << height << "\n";
    stoa::EditorLabApp app;
    app.soundInWindow = std::find(forwarded.begin(), forwarded.end(), "--render") == forwarded.end() &&
                        std::find(forwarded.begin(), forwarded.end(), "--screenshot") == forwarded.end();
    app.stopOnMissingAssets = !app.soundInWindow;   // a picture with a piece missing is not the scene
    return stoa::runLabOnCase(app, STOA_LAB_BUILD_INFO, argv[0], "Stoa editor -- " + scene.filename().string(), cases.str(),
                              "scene", forwarded);
}
