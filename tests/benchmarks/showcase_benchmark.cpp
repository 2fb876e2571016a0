// showcase_benchmark [--runs R] [--size WxH] [--picture FILE.png] [--scene FILE.json]: the showcase (stoa-editor
// --scene showcase, docs/showcase.md) drawn headless with the solutions' code,
// medians of R frames (default 7) at 1280x720:
//   - the frame time as the editor draws it (no waits between passes);
//   - each pass's own time and its share of the frame, the GPU waited for
//     after every pass (glFinish: on llvmpipe the CPU is the GPU, so the
//     waits cost little, but the sum is a little above the frame time);
//   - what the frame held: objects culled, too small and drawn per level of
//     detail, point lights and their tile-list entries, agents.
// The crowd walks and the lights wander 1/30 s between frames. --picture saves
// the last frame (to compare a GPU's picture with llvmpipe's). --scene draws
// another scene file the same way (a larger field or light swarm: the editor's
// caps, docs/instructor-guide.md).

#include "BenchmarkTiming.hpp"

#include "editor_app.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/lab/CaseManifest.hpp>

#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace stoa;
using namespace stoa::benchmark;

namespace {

void showcaseFigures(int runs, glm::ivec2 size, const std::string& picture, const std::filesystem::path& scene) {
    const EditorScene loaded = loadEditorScene(scene);
    std::ostringstream cases;
    cases << "lab = 11_editor\n\n[case showcase]\ndescription = the showcase\nscene = " << scene.string()
          << "\ncamera = orbit\ntarget = " << loaded.camera.target.x << ' ' << loaded.camera.target.y << ' '
          << loaded.camera.target.z << "\ndistance = " << loaded.camera.distance << "\nyaw = " << loaded.camera.yawDegrees
          << "\npitch = " << loaded.camera.pitchDegrees << "\nfar = 400\nresolution = " << size.x << ' ' << size.y << "\n";
    const LabManifest manifest = parseManifest(cases.str(), "showcase_benchmark");

    HeadlessContext context;
    std::printf("%s (headless, %s), %dx%d, medians of %d frames:\n", scene.filename().string().c_str(),
                context.description().c_str(), size.x, size.y, runs);
    LabResources resources({STOA_SOLUTIONS_DIR, paths::shadersDir()});   // as a solutions build's lab 11 finds its GLSL
    const Framebuffer target(size.x, size.y);
    target.bind();
    EditorLabApp app;
    app.initialize(resources);
    app.loadCase(*manifest.find("showcase"));
    const auto frame = [&] {
        app.update(1.0f / 30.0f);
        app.render(size);
        glFinish();
    };
    for (int i = 0; i < 2; ++i) frame();   // warm-up: programs, textures, levels of detail

    constexpr int kPasses = static_cast<int>(CoursePass::Count);
    std::vector<double> plain, timedTotal, passes[kPasses];
    CourseStats last;
    for (int run = 0; run < runs; ++run) {   // interleaved: a plain frame, then one with each pass waited for
        app.timePasses = false;
        const Clock::time_point start = Clock::now();
        frame();
        plain.push_back(milliseconds(start, Clock::now()));
        app.timePasses = true;
        frame();
        last = app.pipeline()->stats();
        timedTotal.push_back(1e3 * last.totalSeconds);
        for (int pass = 0; pass < kPasses; ++pass) passes[pass].push_back(1e3 * last.seconds[static_cast<std::size_t>(pass)]);
    }
    const double total = median(timedTotal);
    std::printf("  a frame as the editor draws it: %.1f ms (%.1f frames per second)\n", median(plain), 1e3 / median(plain));
    std::printf("  with a wait after each pass: %.1f ms, of which\n", total);
    for (int pass = 0; pass < kPasses; ++pass) {
        const double ms = median(passes[pass]);
        std::printf("    %-18s %7.1f ms  %5.1f %%\n", toString(static_cast<CoursePass>(pass)), ms, 100.0 * ms / total);
    }
    std::printf("  %d objects: %d culled, %d too small, drawn at level 0/1/2/3: %d/%d/%d/%d\n", last.objects, last.culled,
                last.tooSmall, last.perLevel[0], last.perLevel[1], last.perLevel[2], last.perLevel[3]);
    std::printf("  %d point lights (%ld tile-list entries), %d agents\n", last.pointLights, last.tileListEntries, last.agents);
    if (!picture.empty()) {
        target.readColor().savePng(picture);
        std::printf("  the last frame: %s\n", picture.c_str());
    }
}

} // namespace

int main(int argc, char** argv) {
    int runs = 7;
    glm::ivec2 size(1280, 720);
    std::string picture;
    std::filesystem::path scene = paths::assetsDir() / "scenes" / "showcase.json";
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) {
            runs = std::atoi(argv[++i]);
            if (runs < 1 || runs > 1000) {
                std::fprintf(stderr, "showcase_benchmark: --runs takes 1 to 1000\n");
                return 2;
            }
        } else if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc) {
            char x = 0;
            std::istringstream text(argv[++i]);
            if (!(text >> size.x >> x >> size.y) || x != 'x' || size.x < 64 || size.y < 64 || size.x > 4096 || size.y > 4096) {
                std::fprintf(stderr, "showcase_benchmark: --size takes WIDTHxHEIGHT, e.g. 1280x720\n");
                return 2;
            }
        } else if (std::strcmp(argv[i], "--picture") == 0 && i + 1 < argc) {
            picture = argv[++i];
        } else if (std::strcmp(argv[i], "--scene") == 0 && i + 1 < argc) {
            scene = argv[++i];
        } else {
            std::fprintf(stderr, "usage: showcase_benchmark [--runs R] [--size WxH] [--picture FILE.png] [--scene FILE.json]\n");
            return 2;
        }
    }
    try {
        std::printf("showcase_benchmark\n");
        showcaseFigures(runs, size, picture, scene);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "showcase_benchmark: %s\n", error.what());
        return 1;
    }
    return 0;
}
