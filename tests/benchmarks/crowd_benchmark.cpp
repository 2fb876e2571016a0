// crowd_benchmark [--runs R] [--steps S] [--frames F] [--agents N] [--threads T] [--no-render]:
// lab 10's crowd with the solutions' code, on one core and on T (default: all the machine's).
//
// The simulation: the predators_prey world (assets/crowds/predators_prey.xml:
// its wolves' state machine and goats' subsumption stack, its hills and ponds)
// tiled k x k, maps and spawn areas repeated per 60 m tile, with 1,000, 10,000,
// 100,000 and 1,000,000 agents shared over the tiles (a tenth wolves), so that
// the density and the obstacles per square metre stay the example's (44 agents
// per tile at most: 1,000 on 5 x 5 tiles, 10,000 on 16 x 16, 100,000 on
// 48 x 48, 1,000,000 on 151 x 151 with maps of 19,328 x 19,328 texels, 1.9 GB;
// --agents N times only that one). After 30 warm-up steps, R runs (default 7)
// of S steps (default 30) each, S scaled down above 10,000 agents to as many
// agent-steps (1,000,000 agents: 3 warm-up steps, runs of 2 steps); the median
// run is printed as milliseconds per step (wall clock; and the CPU time of the
// stepping thread, which a shared machine's other work does not inflate) and
// nanoseconds per agent per step. The same world is then stepped as far on T
// threads (CrowdSimulation::setThreads), timed the same way, and its agents
// compared with the serial run's bit for bit: "equal" says whether every
// field of every agent and the statistics agree (the program fails if not).
//
// Where the time goes, at 10,000 agents: the same with the goats' <send>
// (the bleat) taken out, with every behaviour cut down to its wandering (no
// senses, moves and map look-ups only), and with every agent standing still
// (the step's fixed cost per agent); then one counted run whose lab code is
// wrapped to count the calls and time each sense by its condition (a clock
// read around every CrowdSenses::holds(), its own overhead subtracted).
//
// The renderer: 10,000 agents of the same two types spread over the
// example's own 60 m footprint (its terrain drawn; the wolves' <attack> taken
// out, so all stay alive), stepped 60 times so the poses differ, seen from
// CrowdView::topDown at 1280x720 on the headless context, with and without shadows; F frames (default 7) of each after a
// warm-up, interleaved, each ending with glFinish(); medians of wall and
// process CPU milliseconds (all threads: llvmpipe rasterizes on several).
// $STOA_HEADLESS picks the backend, $LP_NUM_THREADS llvmpipe's threads.

#include "BenchmarkTiming.hpp"
#include "lab10.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/crowd/CrowdXml.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/lab/Lab.hpp>
#include <stoa/render/CrowdRenderer.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <exception>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace {

using stoa::benchmark::Clock;
using stoa::benchmark::median;
using stoa::benchmark::milliseconds;
using namespace stoa;

constexpr float kTile = 60.0f;   // the example's footprint, metres

double cpuSeconds(clockid_t clock) {
    timespec now{};
    clock_gettime(clock, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

double processSeconds() { return cpuSeconds(CLOCK_PROCESS_CPUTIME_ID); }

struct Example {
    CrowdWorld world;
    GroundMaps maps;
};

Example loadExample() {
    Example e;
    e.world = loadCrowdWorld(paths::assetsDir() / "crowds" / "predators_prey.xml");
    e.maps = loadGroundMaps(e.world.ground, e.world.file);
    return e;
}

/// The example's maps repeated tiles x tiles times at their own resolution.
GroundMaps tiledMaps(const GroundMaps& one, int tiles, glm::vec2 min, glm::vec2 max) {
    GroundMaps maps;
    const auto tile = [&](const GroundGrid& grid, auto& out, const auto& in) {
        const int w = grid.width, h = grid.height;
        out.resize(static_cast<std::size_t>(w) * tiles * h * tiles);
        for (int row = 0; row < h * tiles; ++row)
            for (int col = 0; col < w * tiles; ++col)
                out[static_cast<std::size_t>(row) * w * tiles + col] = in[static_cast<std::size_t>(row % h) * w + col % w];
        return GroundGrid{w * tiles, h * tiles, min, max};
    };
    maps.collision.grid = tile(one.collision.grid, maps.collision.walkable, one.collision.walkable);
    maps.heights.grid = tile(one.heights.grid, maps.heights.values, one.heights.values);
    maps.heights.heightMin = one.heights.heightMin;
    maps.heights.heightMax = one.heights.heightMax;
    return maps;
}

/// The example tiled for `agents` agents (a tenth wolves), 44 per 60 m tile.
Example tiledWorld(const Example& example, int agents) {
    int tiles = 1;
    while (tiles * tiles * 44 < agents) ++tiles;
    Example e;
    e.world = example.world;
    const glm::vec2 min(-0.5f * kTile * tiles), max(0.5f * kTile * tiles);
    e.world.ground.footprintMin = min;
    e.world.ground.footprintMax = max;
    e.maps = tiledMaps(example.maps, tiles, min, max);
    const std::vector<SpawnArea> original = example.world.spawns;   // goats, then wolves
    e.world.spawns.clear();
    const int wolves = agents / 10, goats = agents - wolves;
    const int count = tiles * tiles;
    for (int t = 0; t < count; ++t) {
        const glm::vec2 offset = min + kTile * glm::vec2(t % tiles, t / tiles) - example.world.ground.footprintMin;
        for (const SpawnArea& area : original) {
            SpawnArea copy = area;
            copy.centre += offset;
            const int total = area.type == "wolf" ? wolves : goats;
            copy.count = total / count + (t < total % count ? 1 : 0);
            if (copy.count > 0) e.world.spawns.push_back(copy);
        }
    }
    return e;
}

/// Cuts every behaviour down: `wander` keeps only the wandering (the goats'
/// last layer, the wolves' prowl state without transitions), else all stand still.
void simplify(CrowdWorld& world, bool wander) {
    for (Behaviour& behaviour : world.behaviours) {
        if (behaviour.kind == Behaviour::Kind::Subsumption) {
            Layer layer = behaviour.stack.layers.back();
            layer.when.clear();
            if (!wander) {
                layer.actions.resize(1);
                layer.actions[0].kind = Action::Kind::Stop;
            }
            behaviour.stack.layers = {layer};
        } else {
            MachineState state = behaviour.machine.states[static_cast<std::size_t>(behaviour.machine.initial)];
            state.transitions.clear();
            if (!wander) {
                state.actions.resize(1);
                state.actions[0].kind = Action::Kind::Stop;
            }
            behaviour.machine.states = {state};
            behaviour.machine.initial = 0;
        }
    }
}

void removeSend(CrowdWorld& world) {
    for (Behaviour& behaviour : world.behaviours)
        for (Layer& layer : behaviour.stack.layers)
            layer.actions.erase(std::remove_if(layer.actions.begin(), layer.actions.end(),
                                               [](const Action& a) { return a.kind == Action::Kind::Send; }),
                                layer.actions.end());
}

struct StepTiming {
    double msPerStep = 0.0;
    double cpuMsPerStep = 0.0;   // the stepping thread's (serial) or the process's (parallel)
    std::size_t agents = 0;
    CrowdStatistics statistics;
    std::vector<CrowdAgent> finalAgents;   // kept when asked, for the comparison
};

// A simulation on `code` (CrowdSimulation takes the student's functions from the
// framework's table when it is made).
CrowdSimulation crowdWith(const CrowdWorld& world, const GroundMaps& maps, const CrowdFunctions& code) {
    StudentCodeScope scope;
    studentCode().crowds = code;
    return CrowdSimulation(world, maps);
}

StepTiming timeSteps(const Example& e, int runs, int steps, const CrowdFunctions& code, int threads = 1,
                     int warmUp = 30, bool keepAgents = false) {
    CrowdSimulation crowd = crowdWith(e.world, e.maps, code);
    crowd.setThreads(threads);
    crowd.advance(warmUp);   // warm-up: caches, the herd under way
    const clockid_t cpuClock = threads > 1 ? CLOCK_PROCESS_CPUTIME_ID : CLOCK_THREAD_CPUTIME_ID;
    std::vector<double> perStep, cpuPerStep;
    for (int run = 0; run < runs; ++run) {
        const double cpu = cpuSeconds(cpuClock);
        const Clock::time_point start = Clock::now();
        crowd.advance(steps);
        perStep.push_back(milliseconds(start, Clock::now()) / steps);
        cpuPerStep.push_back((cpuSeconds(cpuClock) - cpu) * 1000.0 / steps);
    }
    StepTiming timing{median(perStep), median(cpuPerStep), crowd.agents().size(), crowd.statistics(), {}};
    if (keepAgents) timing.finalAgents = crowd.agents();
    return timing;
}

bool sameBits(const void* a, const void* b, std::size_t bytes) { return std::memcmp(a, b, bytes) == 0; }

/// Every field of every agent and the statistics, bit for bit.
bool sameCrowd(const StepTiming& a, const StepTiming& b) {
    if (a.finalAgents.size() != b.finalAgents.size()) return false;
    for (std::size_t i = 0; i < a.finalAgents.size(); ++i) {
        const CrowdAgent& p = a.finalAgents[i];
        const CrowdAgent& q = b.finalAgents[i];
        const bool same = p.type == q.type && sameBits(&p.position, &q.position, sizeof p.position) &&
                          sameBits(&p.y, &q.y, 4) && sameBits(&p.heading, &q.heading, 4) && sameBits(&p.speed, &q.speed, 4) &&
                          p.state == q.state && sameBits(&p.timeInState, &q.timeInState, 4) &&
                          sameBits(&p.animationTime, &q.animationTime, 4) && p.animation == q.animation &&
                          p.carrying == q.carrying && p.alive == q.alive && sameBits(&p.deadFor, &q.deadFor, 4) &&
                          sameBits(&p.walkedSinceCrumb, &q.walkedSinceCrumb, 4) && p.messages == q.messages &&
                          p.nextMessages == q.nextMessages;
        if (!same) return false;
    }
    const CrowdStatistics& s = a.statistics;
    const CrowdStatistics& t = b.statistics;
    return s.living == t.living && s.attacks == t.attacks && s.blockedMoves == t.blockedMoves &&
           s.samplesOnGround == t.samplesOnGround && s.crumbs == t.crumbs && s.delivered == t.delivered;
}

// The counted run: every lab call counted, every sense timed by its kind.

constexpr int kKinds = 11;
const char* const kKindNames[kKinds] = {"always", "sees",     "near",          "carrying", "at-base", "sees-sample",
                                        "smells-crumb", "blocked", "time-in-state", "message", "chance"};
struct Counters {
    long long walkable = 0, height = 0, machine = 0, layers = 0;
    std::array<long long, kKinds> senses{};
    std::array<double, kKinds> senseNs{};
};
Counters g_counters;
double g_clockOverheadNs = 0.0;

class TimedSenses final : public CrowdSenses {
public:
    explicit TimedSenses(const CrowdSenses& inner) : m_inner(inner) {}
    bool holds(const Condition& condition) const override {
        const auto kind = static_cast<std::size_t>(condition.kind);
        const Clock::time_point start = Clock::now();
        const bool result = m_inner.holds(condition);
        g_counters.senseNs[kind] += std::chrono::duration<double, std::nano>(Clock::now() - start).count() - g_clockOverheadNs;
        ++g_counters.senses[kind];
        return result;
    }

private:
    const CrowdSenses& m_inner;
};

CrowdFunctions countingCode() {
    CrowdFunctions code = studentCode().crowds;
    code.walkableAt = [](const CollisionMap& map, glm::vec2 xz) {
        ++g_counters.walkable;
        return stoa::walkableAt(map, xz);
    };
    code.heightAt = [](const HeightField& field, glm::vec2 xz) {
        ++g_counters.height;
        return stoa::heightAt(field, xz);
    };
    code.stepStateMachine = [](const StateMachine& machine, int current, const CrowdSenses& senses,
                               std::vector<const Action*>& actions) {
        ++g_counters.machine;
        return stoa::stepStateMachine(machine, current, TimedSenses(senses), actions);
    };
    code.arbitrateLayers = [](const SubsumptionStack& stack, const CrowdSenses& senses) {
        ++g_counters.layers;
        return stoa::arbitrateLayers(stack, TimedSenses(senses));
    };
    return code;
}

/// What one clock read costs (two reads back to back), the least of five rounds.
void measureClockOverhead() {
    double least = 1e9;
    for (int round = 0; round < 5; ++round) {
        double sum = 0.0;
        for (int i = 0; i < 100000; ++i) {
            const Clock::time_point a = Clock::now();
            sum += std::chrono::duration<double, std::nano>(Clock::now() - a).count();
        }
        least = std::min(least, sum / 100000.0);
    }
    g_clockOverheadNs = least;
}

/// Serial and parallel at 1,000 to 1,000,000 agents; false if a parallel crowd differs from the serial one.
bool scalingFigures(const Example& example, int runs, int steps, int onlyAgents, int threads) {
    std::printf("  %9s %8s %9s %9s %9s %9s %8s %7s %9s %8s %8s %6s\n", "agents", "tiles", "serial ms", "CPU ms",
                "ns/agent", "parallel", "CPU ms", "speedup", "living", "attacks", "blocked", "equal");
    bool allEqual = true;
    for (const int agents : {1000, 10000, 100000, 1000000}) {
        if (onlyAgents > 0 && agents != onlyAgents) continue;
        const Example e = tiledWorld(example, agents);
        // As many agent-steps per run above 10,000 agents as at 10,000.
        const int runSteps = agents > 10000 ? std::max(2, steps * 10000 / agents) : steps;
        const int warmUp = agents > 100000 ? 3 : 30;
        const StepTiming serial = timeSteps(e, runs, runSteps, studentCode().crowds, 1, warmUp, true);
        const StepTiming parallel = timeSteps(e, runs, runSteps, studentCode().crowds, threads, warmUp, true);
        const bool equal = sameCrowd(serial, parallel);
        allEqual = allEqual && equal;
        const int tiles = static_cast<int>(std::lround((e.world.ground.footprintMax.x - e.world.ground.footprintMin.x) / kTile));
        std::printf("  %9zu %5dx%-3d %9.3f %9.3f %9.0f %9.3f %8.3f %6.2fx %9d %8d %8d %6s\n", serial.agents, tiles, tiles,
                    serial.msPerStep, serial.cpuMsPerStep, serial.msPerStep * 1e6 / static_cast<double>(serial.agents),
                    parallel.msPerStep, parallel.cpuMsPerStep, serial.msPerStep / parallel.msPerStep,
                    serial.statistics.living, serial.statistics.attacks, serial.statistics.blockedMoves,
                    equal ? "yes" : "NO");
        std::fflush(stdout);
    }
    std::printf("  serial and parallel crowds %s\n", allEqual ? "equal bit for bit at every size"
                                                              : "DIFFER: the parallel step is broken");
    return allEqual;
}

/// The lab's walkableAt() and heightAt() alone: called at every living
/// agent's position and 1 m ahead of it, in the step's order (cell by cell),
/// as often as a step calls them; the median of `runs` rounds.
void labLookUps(const CrowdSimulation& crowd, const CrowdFunctions& code, int runs, double walkablePerStep,
                double heightPerStep) {
    std::vector<glm::vec2> points;
    for (const CrowdAgent& agent : crowd.agents())
        if (agent.alive) points.push_back(agent.position);
    std::sort(points.begin(), points.end(), [](glm::vec2 a, glm::vec2 b) {
        const int ra = static_cast<int>(std::floor(a.y / 7.0f)), rb = static_cast<int>(std::floor(b.y / 7.0f));
        return ra != rb ? ra < rb : a.x < b.x;
    });
    std::vector<double> walkableNs, heightNs;
    int sink = 0;   // read below, so that the calls are not optimized away
    float heightSink = 0.0f;
    for (int run = 0; run < runs; ++run) {
        Clock::time_point start = Clock::now();
        for (const glm::vec2 p : points) sink += code.walkableAt(crowd.maps().collision, p + glm::vec2(0.0f, 1.0f)) ? 1 : 0;
        walkableNs.push_back(milliseconds(start, Clock::now()) * 1e6 / static_cast<double>(points.size()));
        start = Clock::now();
        for (const glm::vec2 p : points) heightSink += code.heightAt(crowd.maps().heights, p);
        heightNs.push_back(milliseconds(start, Clock::now()) * 1e6 / static_cast<double>(points.size()));
    }
    const double walkable = median(walkableNs), height = median(heightNs);
    std::printf("  the lab's look-ups alone (%zu points in the step's order): walkableAt %.1f ns, heightAt %.1f ns a "
                "call, %.3f + %.3f ms a step%s\n",
                points.size(), walkable, height, walkable * walkablePerStep * 1e-6, height * heightPerStep * 1e-6,
                sink < 0 || heightSink < -1e30f ? " " : "");
}

bool simulationFigures(int runs, int steps, int onlyAgents, int threads) {
    const Example example = loadExample();
    std::printf("simulation: predators_prey tiled (60 m tiles of %dx%d texels, 44 agents per tile, a tenth wolves), "
                "%d warm-up steps, median of %d runs of %d steps; serial on one core, parallel on %d threads\n",
                example.maps.collision.grid.width, example.maps.collision.grid.height, 30, runs, steps, threads);
    const bool equal = scalingFigures(example, runs, steps, onlyAgents, threads);
    if (onlyAgents > 0 && onlyAgents != 10000) return equal;

    std::printf("where the time goes at 10,000 agents (ms per step, median of %d runs):\n", runs);
    const Example full = tiledWorld(example, 10000);
    Example noSend = full, wander = full, stand = full;
    removeSend(noSend.world);
    simplify(wander.world, true);
    simplify(stand.world, false);
    const double fullMs = timeSteps(full, runs, steps, studentCode().crowds).msPerStep;
    const double noSendMs = timeSteps(noSend, runs, steps, studentCode().crowds).msPerStep;
    const double wanderMs = timeSteps(wander, runs, steps, studentCode().crowds).msPerStep;
    const double standMs = timeSteps(stand, runs, steps, studentCode().crowds).msPerStep;
    std::printf("  %-58s %8.3f\n", "the world as it is", fullMs);
    std::printf("  %-58s %8.3f  (<send> costs %.3f)\n", "without the goats' <send> (bleat to all within 6 m)", noSendMs,
                fullMs - noSendMs);
    std::printf("  %-58s %8.3f  (senses and other actions cost %.3f)\n", "wandering only (no conditions, no seek/flee)",
                wanderMs, noSendMs - wanderMs);
    std::printf("  %-58s %8.3f  (moving and the map look-ups cost %.3f)\n", "standing still (the step's fixed cost)",
                standMs, wanderMs - standMs);

    measureClockOverhead();
    g_counters = Counters{};
    CrowdSimulation counted = crowdWith(full.world, full.maps, countingCode());
    counted.advance(30);
    g_counters = Counters{};
    counted.advance(steps);
    const double perStep = 1.0 / steps;
    std::printf("  calls per step (counted run, %d steps): stepStateMachine %.0f, arbitrateLayers %.0f, walkableAt "
                "%.0f, heightAt %.0f\n",
                steps, g_counters.machine * perStep, g_counters.layers * perStep, g_counters.walkable * perStep,
                g_counters.height * perStep);
    labLookUps(counted, studentCode().crowds, runs, g_counters.walkable * perStep, g_counters.height * perStep);
    std::printf("  senses per step, by condition (clock overhead %.0f ns subtracted per call):\n", g_clockOverheadNs);
    for (int k = 0; k < kKinds; ++k) {
        if (g_counters.senses[static_cast<std::size_t>(k)] == 0) continue;
        const double calls = g_counters.senses[static_cast<std::size_t>(k)] * perStep;
        const double ms = g_counters.senseNs[static_cast<std::size_t>(k)] * perStep * 1e-6;
        std::printf("    %-14s %9.0f calls %8.3f ms %8.0f ns each\n", kKindNames[k], calls, ms, ms * 1e6 / calls);
    }
    return equal;
}

void renderFigures(int frames) {
    Example e = loadExample();
    for (SpawnArea& area : e.world.spawns) {
        area.count = area.type == "wolf" ? 1000 : 9000;
        area.centre = glm::vec2(0.0f);
        area.radius = 28.0f;
    }
    // So dense, the wolves would kill most goats in a few steps: here they only pounce.
    for (Behaviour& behaviour : e.world.behaviours)
        for (MachineState& state : behaviour.machine.states)
            state.actions.erase(std::remove_if(state.actions.begin(), state.actions.end(),
                                               [](const Action& a) { return a.kind == Action::Kind::Attack; }),
                                state.actions.end());
    CrowdSimulation crowd(e.world, e.maps);
    crowd.advance(60);

    HeadlessContext context;
    std::printf("renderer: %s\n", context.description().c_str());
    LabResources resources({paths::shadersDir()});
    const CrowdPrograms programs = CrowdPrograms::load(
        [&](const std::string& vertex, const std::string& fragment) -> const Program& {
            return resources.loadProgram(vertex, fragment);
        });
    const glm::ivec2 size(1280, 720);
    const Framebuffer target(size.x, size.y);
    target.bind();
    CrowdRenderer renderer(programs, crowd);
    const CrowdView view = CrowdView::topDown(crowd.maps().collision.grid, static_cast<float>(size.x) / size.y);
    std::size_t triangles = 0;
    for (const CrowdAgent& agent : crowd.agents())
        triangles += agent.alive ? renderer.model(static_cast<std::size_t>(agent.type)).model.triangles.size() : 0;
    std::printf("  %zu agents (%d living, %.1fM model triangles) on the example's terrain, %dx%d, top-down view, "
                "median of %d frames after a warm-up\n",
                crowd.agents().size(), crowd.statistics().living, static_cast<double>(triangles) * 1e-6, size.x, size.y,
                frames);
    struct Measured {
        const char* name;
        bool shadows;
        std::vector<double> wall, cpu;
    };
    std::vector<Measured> measured{{"with shadows", true, {}, {}}, {"without shadows", false, {}, {}}};
    const auto draw = [&](Measured& m, bool record) {
        CrowdDrawOptions options;
        options.shadows = m.shadows;
        target.bind();
        glFinish();
        const double cpu = processSeconds();
        const Clock::time_point start = Clock::now();
        renderer.render(crowd, view, size, options);
        glFinish();
        if (!record) return;
        m.wall.push_back(milliseconds(start, Clock::now()));
        m.cpu.push_back((processSeconds() - cpu) * 1000.0);
    };
    for (Measured& m : measured) draw(m, false);
    for (int frame = 0; frame < frames; ++frame)
        for (Measured& m : measured) draw(m, true);
    std::printf("  %-18s %10s %10s\n", "", "wall ms", "CPU ms");
    for (const Measured& m : measured) std::printf("  %-18s %10.1f %10.1f\n", m.name, median(m.wall), median(m.cpu));
    std::printf("  shadows cost %.2fx the frame without\n", median(measured[0].wall) / median(measured[1].wall));
}

} // namespace

int main(int argc, char** argv) {
    int runs = 7, steps = 30, frames = 7, onlyAgents = 0;
    int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    bool render = true;
    for (int i = 1; i < argc; ++i) {
        int* value = nullptr;
        if (std::strcmp(argv[i], "--runs") == 0) value = &runs;
        else if (std::strcmp(argv[i], "--steps") == 0) value = &steps;
        else if (std::strcmp(argv[i], "--frames") == 0) value = &frames;
        else if (std::strcmp(argv[i], "--agents") == 0) value = &onlyAgents;
        else if (std::strcmp(argv[i], "--threads") == 0) value = &threads;
        else if (std::strcmp(argv[i], "--no-render") == 0) {
            render = false;
            continue;
        }
        if (!value || i + 1 >= argc || (*value = std::atoi(argv[++i])) < 1 || *value > 1000000) {
            std::fprintf(stderr, "usage: crowd_benchmark [--runs R] [--steps S] [--frames F] [--agents N] [--threads T] "
                                 "[--no-render]\n"
                                 "  defaults: 7 runs of 30 steps, 7 frames, as many threads as the machine has\n");
            return 2;
        }
    }
    std::printf("crowd_benchmark");
    for (int i = 1; i < argc; ++i) std::printf(" %s", argv[i]);
    std::printf("\n");
    try {
        const bool equal = simulationFigures(runs, steps, onlyAgents, threads);
        if (render) renderFigures(frames);
        if (!equal) return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "crowd_benchmark: %s\n", error.what());
        return 1;
    }
    return 0;
}
