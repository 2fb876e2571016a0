// stoa-crowds: any crowd world in a window, with lab 10's app and the code of
// the track it was built from (yours, in your build).
//
//   stoa-crowds WORLD.xml                      run it in a window (keys: F1 and the help it prints)
//   stoa-crowds WORLD.xml --steps N --screenshot FILE
//                                              N steps, the window's first frame saved as PNG, quit
//   stoa-crowds WORLD.xml --steps N --render FILE [--backend osmesa|egl]
//                                              the same picture headless
//   stoa-crowds --make-maps DIR                write the example worlds' ground maps
//                                              (assets/crowds/ holds what it writes)
// A world named without a folder is looked up in assets/crowds/ too, so
// `stoa-crowds mars_explorers.xml` runs the explorers.

#include "crowd_app.hpp"

#include <stoa/lab/LabApp.hpp>
#include <stoa/scene/GroundMapMaker.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace {

// The usage: asked for (--help, problem nullptr) on stdout, exit 0; after a
// problem on stderr, exit 2.
int usage(const char* problem) {
    if (problem) std::fprintf(stderr, "stoa-crowds: %s\n", problem);
    std::fprintf(problem ? stderr : stdout,
                 "usage: stoa-crowds WORLD.xml [--steps N] [--view top|camera] [--trails on|off]\n"
                 "                   [--screenshot FILE | --render FILE [--backend osmesa|egl]]\n"
                 "       stoa-crowds --make-maps DIR\n"
                 "Runs a crowd world (docs/crowds-xml.md) in a window, or saves one picture of it.\n");
    return problem ? 2 : 0;
}

bool isNumber(const std::string& text) {
    if (text.empty() || text.size() > 6) return false;
    for (const char c : text)
        if (c < '0' || c > '9') return false;
    return true;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() == 2 && args[0] == "--make-maps") {
        try {
            for (const std::filesystem::path& path : stoa::writeExampleGroundMaps(args[1]))
                std::printf("wrote %s\n", path.string().c_str());
            return 0;
        } catch (const std::exception& error) {
            std::fprintf(stderr, "stoa-crowds: %s\n", error.what());
            return 1;
        }
    }
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) return usage(nullptr);
    if (args.empty() || args[0].empty() || args[0][0] == '-')
        return usage(args.empty() ? "the first argument is the world file (none given)" : "the first argument is the world file");
    std::filesystem::path world = args[0];
    std::error_code error;
    if (!std::filesystem::exists(world, error) && world.parent_path().empty())
        world = stoa::paths::assetsDir() / "crowds" / world;
    if (!std::filesystem::exists(world, error)) return usage(("no world file " + args[0]).c_str());
    world = std::filesystem::absolute(world);

    std::string steps = "0", view = "top", trails;
    std::vector<std::string> forwarded;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& flag = args[i];
        const bool hasValue = i + 1 < args.size();
        if (flag == "--steps" && hasValue) {
            steps = args[++i];
            if (!isNumber(steps)) return usage("--steps takes a whole number of steps, 0 to 20000");
        } else if (flag == "--view" && hasValue) {
            view = args[++i];
            if (view != "top" && view != "camera") return usage("--view is top or camera");
        } else if (flag == "--trails" && hasValue) {
            trails = args[++i];
            if (trails != "on" && trails != "off") return usage("--trails is on or off");
        } else if ((flag == "--screenshot" || flag == "--backend" || flag == "--render") && hasValue) {
            forwarded.push_back(flag);
            forwarded.push_back(args[++i]);
        } else {
            return usage(("unknown or incomplete flag " + flag).c_str());
        }
    }

    // One case for the lab app.
    std::ostringstream cases;
    cases << "lab = 10_crowds\ntitle = stoa-crowds\n\n[case world]\ndescription = " << world.filename().string()
          << "\nworld = " << world.string() << "\nsteps = " << steps << "\nview = " << view
          << "\ncamera = orbit\ntarget = 0 0 0\ndistance = 34\nyaw = 20\npitch = 40\nfar = 200\n";
    if (!trails.empty()) cases << "trails = " << trails << "\n";
    stoa::CrowdApp app;
    return stoa::runLabOnCase(app, STOA_LAB_BUILD_INFO, argv[0], "Stoa crowds -- " + world.filename().string(), cases.str(),
                              "world", forwarded);
}
