#pragma once
// What the crowd tests share (CrowdSimulationTests.cpp, CrowdDeterminismTests.cpp):
// small, correct implementations of the lab's crowd functions, written here
// independently of solutions/10_crowds (so tests/labs/, which the student
// release leaves out), a simulation made on them, the example worlds, and a
// bit-for-bit comparison of two crowds.

#include "catch.hpp"

#include <stoa/core/Paths.hpp>
#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/crowd/CrowdXml.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace stoa::crowdtest {

// The lab code the simulations run on.

inline bool allHold(const std::vector<Condition>& when, const CrowdSenses& senses) {
    return std::all_of(when.begin(), when.end(), [&](const Condition& c) { return senses.holds(c); });
}

inline int testStateMachine(const StateMachine& machine, int current, const CrowdSenses& senses,
                     std::vector<const Action*>& actions) {
    int next = current;
    for (const Transition& transition : machine.states.at(static_cast<std::size_t>(current)).transitions) {
        if (allHold(transition.when, senses)) {
            next = transition.target;
            break;
        }
    }
    actions.clear();
    for (const Action& action : machine.states.at(static_cast<std::size_t>(next)).actions) actions.push_back(&action);
    return next;
}

inline int testLayers(const SubsumptionStack& stack, const CrowdSenses& senses) {
    for (std::size_t i = 0; i < stack.layers.size(); ++i)
        if (allHold(stack.layers[i].when, senses)) return static_cast<int>(i);
    return -1;
}

inline bool testWalkable(const CollisionMap& map, glm::vec2 xz) {
    const GroundGrid& g = map.grid;
    const float u = (xz.x - g.footprintMin.x) * static_cast<float>(g.width) / (g.footprintMax.x - g.footprintMin.x);
    const float v = (xz.y - g.footprintMin.y) * static_cast<float>(g.height) / (g.footprintMax.y - g.footprintMin.y);
    if (!(u >= 0.0f && v >= 0.0f && u < static_cast<float>(g.width) && v < static_cast<float>(g.height))) return false;
    const int col = std::min(static_cast<int>(u), g.width - 1), row = std::min(static_cast<int>(v), g.height - 1);
    return map.walkable[static_cast<std::size_t>(row * g.width + col)] != 0;
}

inline float testHeight(const HeightField& field, glm::vec2 xz) {
    const GroundGrid& g = field.grid;
    const float u = std::clamp((xz.x - g.footprintMin.x) * g.width / (g.footprintMax.x - g.footprintMin.x) - 0.5f, 0.0f,
                               static_cast<float>(g.width - 1));
    const float v = std::clamp((xz.y - g.footprintMin.y) * g.height / (g.footprintMax.y - g.footprintMin.y) - 0.5f,
                               0.0f, static_cast<float>(g.height - 1));
    const int c0 = static_cast<int>(u), r0 = static_cast<int>(v);
    const int c1 = std::min(c0 + 1, g.width - 1), r1 = std::min(r0 + 1, g.height - 1);
    const float s = u - c0, t = v - r0;
    const auto at = [&](int c, int r) { return field.values[static_cast<std::size_t>(r * g.width + c)]; };
    const float value = (1 - t) * ((1 - s) * at(c0, r0) + s * at(c1, r0)) + t * ((1 - s) * at(c0, r1) + s * at(c1, r1));
    return field.heightMin + (field.heightMax - field.heightMin) * value;
}

/// The simulation needs only these four; the key-frame functions stay unset.
inline CrowdFunctions testCode() {
    CrowdFunctions code;
    code.stepStateMachine = &testStateMachine;
    code.arbitrateLayers = &testLayers;
    code.walkableAt = &testWalkable;
    code.heightAt = &testHeight;
    return code;
}

/// A simulation on `code` (CrowdSimulation takes the student's functions from the
/// table when it is made, so the table goes back as it was at once).
inline CrowdSimulation crowdWith(const CrowdWorld& world, GroundMaps maps, const CrowdFunctions& code) {
    StudentCodeScope scope;
    studentCode().crowds = code;
    return CrowdSimulation(world, std::move(maps));
}

struct Example {
    CrowdWorld world;
    GroundMaps maps;
};

inline Example example(const std::string& name) {
    Example e;
    e.world = loadCrowdWorld(paths::assetsDir() / "crowds" / name);
    e.maps = loadGroundMaps(e.world.ground, e.world.file);
    return e;
}

inline bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

inline bool sameBits(glm::vec2 a, glm::vec2 b) { return sameBits(a.x, b.x) && sameBits(a.y, b.y); }

/// Every field of every agent, the samples and the crumbs, bit for bit.
inline void requireIdentical(const CrowdSimulation& a, const CrowdSimulation& b) {
    REQUIRE(a.agents().size() == b.agents().size());
    for (std::size_t i = 0; i < a.agents().size(); ++i) {
        const CrowdAgent& p = a.agents()[i];
        const CrowdAgent& q = b.agents()[i];
        INFO("agent " << i);
        REQUIRE(sameBits(p.position, q.position));
        REQUIRE(sameBits(p.y, q.y));
        REQUIRE(sameBits(p.heading, q.heading));
        REQUIRE(sameBits(p.speed, q.speed));
        REQUIRE(p.state == q.state);
        REQUIRE(sameBits(p.timeInState, q.timeInState));
        REQUIRE(sameBits(p.animationTime, q.animationTime));
        REQUIRE(p.animation == q.animation);
        REQUIRE(p.carrying == q.carrying);
        REQUIRE(p.alive == q.alive);
        REQUIRE(sameBits(p.deadFor, q.deadFor));
        REQUIRE(sameBits(p.walkedSinceCrumb, q.walkedSinceCrumb));
        REQUIRE(p.messages == q.messages);
    }
    REQUIRE(a.samples().size() == b.samples().size());
    for (std::size_t i = 0; i < a.samples().size(); ++i) REQUIRE(sameBits(a.samples()[i], b.samples()[i]));
    REQUIRE(a.crumbs().size() == b.crumbs().size());
    for (std::size_t i = 0; i < a.crumbs().size(); ++i) REQUIRE(sameBits(a.crumbs()[i], b.crumbs()[i]));
    REQUIRE(a.statistics().attacks == b.statistics().attacks);
    REQUIRE(a.statistics().delivered == b.statistics().delivered);
    REQUIRE(a.statistics().blockedMoves == b.statistics().blockedMoves);
}

inline int lineOf(const std::string& text, const std::string& marker) {
    const std::size_t at = text.find(marker);
    REQUIRE(at != std::string::npos);
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

} // namespace stoa::crowdtest
