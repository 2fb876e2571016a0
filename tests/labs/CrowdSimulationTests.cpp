// Lab 10: CrowdSimulation (stoa/crowd/CrowdSimulation.hpp) on the example
// worlds (assets/crowds/mars_explorers.xml and predators_prey.xml) and on
// small worlds written here, with the lab code of CrowdTestCode.hpp (that a
// crowd depends on its world and seed alone: CrowdDeterminismTests.cpp). Checked:
//   - no living agent ever stands on a texel the collision map blocks (a
//     look-up in double, every step of 400 in both worlds, and at the start);
//   - every living agent's y is heightAt(position) after every step (of
//     1,300), but the step it comes back, which has a case of its own;
//   - an agent's trail holds its position every trailEvery steps, oldest
//     first, the last trailLength of them once the ring has turned;
//   - the explorers deliver samples within 2,400 steps and leave crumbs;
//   - the wolves attack goats within 1,200 steps, and an attacked goat comes
//     back after respawnSeconds (241 steps of 1/30 s), on walkable ground
//     within its spawn area (the first comes back at step 1,208: 1,500 steps);
//     at heightAt() of its new place;
//   - every agent plays the animation of the state or layer it is in;
//   - a state or layer index out of range from the lab code throws
//     std::out_of_range naming the function (-1 from arbitrateLayers is fine);
//   - a <spawn> or <samples> area without walkable ground throws InputError
//     naming the world file and that element's line; a walkableAt() that
//     refuses white ground is named in the message.

#include "CrowdTestCode.hpp"
#include "catch.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/crowd/CrowdXml.hpp>


#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

using namespace stoa;
using namespace stoa::crowdtest;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// Whether every point within 1e-4 m of `xz` lies on a blocked texel or off
/// the map (so a point on a texel's edge is not held against the simulation).
bool standsOnBlockedGround(const CollisionMap& map, glm::vec2 xz) {
    const GroundGrid& g = map.grid;
    const double e = 1e-4;
    for (const double dx : {-e, 0.0, e}) {
        for (const double dz : {-e, 0.0, e}) {
            const double u = (xz.x + dx - g.footprintMin.x) / (static_cast<double>(g.footprintMax.x) - g.footprintMin.x) * g.width;
            const double v = (xz.y + dz - g.footprintMin.y) / (static_cast<double>(g.footprintMax.y) - g.footprintMin.y) * g.height;
            if (u < 0.0 || v < 0.0 || u >= g.width || v >= g.height) continue;
            if (map.walkable[static_cast<std::size_t>(static_cast<int>(v) * g.width + static_cast<int>(u))]) return false;
        }
    }
    return true;
}

/// One walker type with a one-state machine (or a one-layer stack), a
/// `<spawn>` (and `<samples>` when asked) at (0, 0); lines as in the text.
std::string smallWorld(bool subsumption, const std::string& samples = "") {
    std::string text = "<world seed=\"5\">\n"
                       "  <ground collision=\"c.png\" min=\"-10 -10\" max=\"10 10\"/>\n"
                       "  <type name=\"walker\" model=\"w.md2\" skin=\"w.png\" behaviour=\"walk\"/>\n";
    text += subsumption ? "  <behaviour name=\"walk\" kind=\"subsumption\">\n"
                          "    <layer name=\"go\" animation=\"run\"><wander/></layer>\n"
                          "  </behaviour>\n"
                        : "  <behaviour name=\"walk\" kind=\"fsm\">\n"
                          "    <state name=\"go\" animation=\"run\"><wander/></state>\n"
                          "  </behaviour>\n";
    text += samples;
    text += "  <spawn type=\"walker\" count=\"3\" x=\"0\" z=\"0\" radius=\"2\"/>\n"
            "</world>\n";
    return text;
}

/// flatGround over [-10, 10]^2 (20 x 20 texels of 1 m) with the square [-4, 4]^2 blocked.
GroundMaps groundWithBlockedMiddle() {
    GroundMaps maps = flatGround({-10.0f, -10.0f}, {10.0f, 10.0f}, 20);
    for (int row = 6; row < 14; ++row)
        for (int col = 6; col < 14; ++col) maps.collision.walkable[static_cast<std::size_t>(row * 20 + col)] = 0;
    return maps;
}

} // namespace

TEST_CASE("Crowd: no agent ever stands on a texel the collision map blocks", "[crowd][simulation]") {
    for (const char* name : {"mars_explorers.xml", "predators_prey.xml"}) {
        const Example e = example(name);
        CrowdSimulation crowd = crowdWith(e.world, e.maps, testCode());
        int moves = 0;
        for (int step = 0; step <= 400; ++step) {
            if (step > 0) crowd.step();
            for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
                const CrowdAgent& agent = crowd.agents()[i];
                if (!agent.alive) continue;
                INFO(name << ", step " << step << ", agent " << i << " at (" << agent.position.x << ", "
                          << agent.position.y << ")");
                REQUIRE_FALSE(standsOnBlockedGround(crowd.maps().collision, agent.position));
                moves += agent.speed > 0.0f;
            }
        }
        INFO(name);
        CHECK(crowd.statistics().blockedMoves > 0);   // the walls and ponds were met, not missed
        CHECK(moves > 1000);
    }
}

TEST_CASE("Crowd: every living agent stands at heightAt(position) after each step", "[crowd][simulation]") {
    const Example e = example("predators_prey.xml");
    CrowdSimulation crowd = crowdWith(e.world, e.maps, testCode());
    float lowest = 1e9f, highest = -1e9f;
    for (int step = 0; step < 1300; ++step) {
        std::vector<bool> wasAlive;
        for (const CrowdAgent& agent : crowd.agents()) wasAlive.push_back(agent.alive);
        crowd.step();
        for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
            const CrowdAgent& agent = crowd.agents()[i];
            if (!agent.alive || !wasAlive[i]) continue;   // the step an agent comes back: the next case
            INFO("step " << step << ", agent " << i);
            REQUIRE(sameBits(agent.y, testHeight(crowd.maps().heights, agent.position)));
            lowest = std::min(lowest, agent.y);
            highest = std::max(highest, agent.y);
        }
    }
    CHECK(highest - lowest > 0.5f);   // the hills are not flat under the herd
}

TEST_CASE("Crowd: an agent's trail is its position every trailEvery steps, oldest first, the last trailLength",
          "[crowd][simulation]") {
    const Example e = example("predators_prey.xml");
    CrowdSimulation crowd = crowdWith(e.world, e.maps, testCode());
    const std::size_t count = crowd.agents().size();
    REQUIRE(crowd.trail(0).empty());   // nothing recorded before the first step
    // Past one turn of the ring and a bit, so the oldest positions have been overwritten.
    const int steps = (CrowdSimulation::trailLength + 5) * CrowdSimulation::trailEvery;
    std::vector<std::vector<glm::vec2>> recorded(count);
    for (int step = 1; step <= steps; ++step) {
        crowd.step();
        if (step % CrowdSimulation::trailEvery != 0) continue;
        for (std::size_t i = 0; i < count; ++i) recorded[i].push_back(crowd.agents()[i].position);
        if (step == 2 * CrowdSimulation::trailEvery) REQUIRE(crowd.trail(count - 1).size() == 2);
    }
    for (std::size_t i = 0; i < count; ++i) {
        INFO("agent " << i);
        const std::vector<glm::vec2> trail = crowd.trail(i);
        REQUIRE(trail.size() == static_cast<std::size_t>(CrowdSimulation::trailLength));
        const std::size_t first = recorded[i].size() - trail.size();
        for (std::size_t k = 0; k < trail.size(); ++k) {
            REQUIRE(sameBits(trail[k].x, recorded[i][first + k].x));
            REQUIRE(sameBits(trail[k].y, recorded[i][first + k].y));
        }
    }
}

// A regression test: step() once placed a goat that came back without setting
// its y, so for that step it stood at the height of the place it died
// (predators_prey: goat 30 dies at step 967 at y 1.91 and comes back at step
// 1208, where the ground is 5.79 m).
TEST_CASE("Crowd: a goat that comes back stands at heightAt of its new place", "[crowd][simulation]") {
    const Example e = example("predators_prey.xml");
    CrowdSimulation crowd = crowdWith(e.world, e.maps, testCode());
    int comebacks = 0;
    for (int step = 1; step <= 1500; ++step) {
        std::vector<bool> wasAlive;
        for (const CrowdAgent& agent : crowd.agents()) wasAlive.push_back(agent.alive);
        crowd.step();
        for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
            const CrowdAgent& agent = crowd.agents()[i];
            if (wasAlive[i] || !agent.alive) continue;
            INFO("agent " << i << " back at step " << step);
            CHECK(agent.y == testHeight(crowd.maps().heights, agent.position));
            ++comebacks;
        }
    }
    CHECK(comebacks > 0);
}

TEST_CASE("Crowd: the explorers deliver samples and leave crumbs", "[crowd][simulation]") {
    const Example e = example("mars_explorers.xml");
    CrowdSimulation crowd = crowdWith(e.world, e.maps, testCode());
    const int samplesAtStart = crowd.statistics().samplesOnGround;
    CHECK(samplesAtStart == 55);
    int mostCrumbs = 0, mostCarrying = 0;
    for (int step = 0; step < 2400; ++step) {
        crowd.step();
        const CrowdStatistics s = crowd.statistics();
        mostCrumbs = std::max(mostCrumbs, s.crumbs);
        mostCarrying = std::max(mostCarrying, s.carrying);
        // Samples are neither made nor lost: on the ground, carried or delivered.
        REQUIRE(s.samplesOnGround + s.carrying + s.delivered == samplesAtStart);
    }
    CHECK(crowd.statistics().delivered > 0);
    CHECK(mostCarrying > 0);
    CHECK(mostCrumbs > 0);
}

TEST_CASE("Crowd: the wolves attack goats, and a goat comes back after respawnSeconds", "[crowd][simulation]") {
    const Example e = example("predators_prey.xml");
    CrowdSimulation crowd = crowdWith(e.world, e.maps, testCode());
    const int goat = crowd.world().findType("goat");
    const double dt = crowd.world().step;
    const int stepsDead = static_cast<int>(std::ceil(CrowdSimulation::respawnSeconds / dt));
    std::vector<long long> diedAt(crowd.agents().size(), -1);
    int deaths = 0, comebacks = 0;
    int attacksBy1200 = 0;
    for (int step = 1; step <= 1500; ++step) {
        if (step == 1201) attacksBy1200 = crowd.statistics().attacks;
        std::vector<bool> wasAlive;
        for (const CrowdAgent& agent : crowd.agents()) wasAlive.push_back(agent.alive);
        crowd.step();
        for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
            const CrowdAgent& agent = crowd.agents()[i];
            if (wasAlive[i] && !agent.alive) {
                CHECK(agent.type == goat);
                diedAt[i] = step;
                ++deaths;
            } else if (!wasAlive[i] && agent.alive) {
                INFO("agent " << i << " died at step " << diedAt[i] << ", back at step " << step);
                // deadFor adds up dt in float: one step either way.
                CHECK(std::abs((step - diedAt[i]) - stepsDead) <= 1);
                const SpawnArea& area = crowd.world().spawns[static_cast<std::size_t>(agent.spawn)];
                CHECK(glm::length(agent.position - area.centre) <= area.radius + 1e-3f);
                CHECK(testWalkable(crowd.maps().collision, agent.position));
                ++comebacks;
            }
        }
    }
    CHECK(crowd.statistics().attacks == deaths);
    CHECK(attacksBy1200 > 0);
    CHECK(comebacks > 0);
}

TEST_CASE("Crowd: every agent plays the animation of the state or layer it is in", "[crowd][simulation]") {
    const Example e = example("predators_prey.xml");
    CrowdSimulation crowd = crowdWith(e.world, e.maps, testCode());
    CHECK(crowd.animationName(0) == "stand");
    std::vector<std::string> seen;
    for (int step = 0; step <= 1500; ++step) {
        for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
            const CrowdAgent& agent = crowd.agents()[i];
            if (!agent.alive) continue;
            const AgentType& type = crowd.world().types[static_cast<std::size_t>(agent.type)];
            const Behaviour& behaviour = crowd.world().behaviours[static_cast<std::size_t>(type.behaviourIndex)];
            // No layer fired (state -1): the agent stands.
            const std::string expected =
                agent.state < 0 ? "stand"
                : behaviour.kind == Behaviour::Kind::StateMachine
                    ? behaviour.machine.states[static_cast<std::size_t>(agent.state)].animation
                    : behaviour.stack.layers[static_cast<std::size_t>(agent.state)].animation;
            INFO("agent " << i << " at step " << step << " in " << crowd.stateName(i));
            REQUIRE(crowd.animationName(agent.animation) == expected);
            if (std::find(seen.begin(), seen.end(), expected) == seen.end()) seen.push_back(expected);
        }
        crowd.step();
    }
    // The wolves run, pounce and rest, the goats run and eat: every animation the world names is played.
    std::sort(seen.begin(), seen.end());
    CHECK(seen == std::vector<std::string>{"attack", "eat", "run", "stand"});
}

TEST_CASE("Crowd: a state or layer out of range from the lab code throws std::out_of_range naming the function",
          "[crowd][simulation]") {
    const GroundMaps maps = flatGround({-10.0f, -10.0f}, {10.0f, 10.0f}, 20);
    const CrowdWorld fsm = parseCrowdWorld(smallWorld(false), "fsm.xml");
    const CrowdWorld layers = parseCrowdWorld(smallWorld(true), "layers.xml");
    for (const int state : {1, -1, 1000}) {
        CrowdFunctions code = testCode();
        static int s_state;
        s_state = state;
        code.stepStateMachine = [](const StateMachine&, int, const CrowdSenses&, std::vector<const Action*>& actions) {
            actions.clear();
            return s_state;
        };
        CrowdSimulation crowd = crowdWith(fsm, maps, code);
        INFO("stepStateMachine returns " << state);
        try {
            crowd.step();
            FAIL("no exception");
        } catch (const std::out_of_range& error) {
            INFO(error.what());
            CHECK(contains(error.what(), "stepStateMachine()"));
            CHECK(contains(error.what(), std::to_string(state)));
        }
    }
    for (const int layer : {1, -2, 77}) {
        CrowdFunctions code = testCode();
        static int s_layer;
        s_layer = layer;
        code.arbitrateLayers = [](const SubsumptionStack&, const CrowdSenses&) { return s_layer; };
        CrowdSimulation crowd = crowdWith(layers, maps, code);
        INFO("arbitrateLayers returns " << layer);
        try {
            crowd.step();
            FAIL("no exception");
        } catch (const std::out_of_range& error) {
            INFO(error.what());
            CHECK(contains(error.what(), "arbitrateLayers()"));
            CHECK(contains(error.what(), std::to_string(layer)));
        }
    }
    // -1 is "no layer fires": the agent stands still.
    CrowdFunctions code = testCode();
    code.arbitrateLayers = [](const SubsumptionStack&, const CrowdSenses&) { return -1; };
    CrowdSimulation crowd = crowdWith(layers, maps, code);
    const glm::vec2 before = crowd.agents()[0].position;
    crowd.advance(3);
    CHECK(crowd.agents()[0].state == -1);
    CHECK(crowd.agents()[0].position == before);
    CHECK(crowd.stateName(0).empty());
}

TEST_CASE("Crowd: a world with more than 32,767 agent types is refused with the limit", "[crowd][simulation]") {
    // CrowdAgent keeps its type in 16 bits.
    Example e = example("predators_prey.xml");
    e.world.types.resize(32768, e.world.types.front());
    try {
        CrowdSimulation crowd = crowdWith(e.world, e.maps, testCode());
        FAIL("no exception");
    } catch (const InputError& error) {
        INFO(error.what());
        CHECK(contains(error.what(), "predators_prey.xml"));
        CHECK(contains(error.message(), "32768 agent types"));
        CHECK(contains(error.message(), "at most 32,767"));
    }
}

TEST_CASE("Crowd: an area without walkable ground throws InputError naming the world file and its line",
          "[crowd][simulation]") {
    const GroundMaps maps = groundWithBlockedMiddle();
    SECTION("a <spawn>") {
        const std::string text = smallWorld(false);
        const CrowdWorld world = parseCrowdWorld(text, "/somewhere/blocked_spawn.xml");
        try {
            CrowdSimulation crowd = crowdWith(world, maps, testCode());
            FAIL("no exception");
        } catch (const InputError& error) {
            INFO(error.what());
            CHECK(error.file() == "/somewhere/blocked_spawn.xml");
            CHECK(error.line() == lineOf(text, "<spawn"));
            CHECK(contains(error.what(), "blocked_spawn.xml"));
            CHECK(contains(error.message(), "walker"));
        }
    }
    SECTION("a <samples>") {
        const std::string text = smallWorld(false, "  <samples count=\"4\" x=\"1\" z=\"-1\" radius=\"2\"/>\n");
        const CrowdWorld world = parseCrowdWorld(text, "blocked_samples.xml");
        try {
            CrowdSimulation crowd = crowdWith(world, maps, testCode());
            FAIL("no exception");
        } catch (const InputError& error) {
            INFO(error.what());
            CHECK(error.file() == "blocked_samples.xml");
            CHECK(error.line() == lineOf(text, "<samples"));
        }
    }
    SECTION("a walkableAt() that refuses white ground is named") {
        const std::string text = smallWorld(false);
        const CrowdWorld world = parseCrowdWorld(text, "white.xml");
        CrowdFunctions code = testCode();
        code.walkableAt = [](const CollisionMap&, glm::vec2) { return false; };
        try {
            CrowdSimulation crowd = crowdWith(world, flatGround({-10.0f, -10.0f}, {10.0f, 10.0f}, 20), code);
            FAIL("no exception");
        } catch (const InputError& error) {
            INFO(error.what());
            CHECK(error.line() == lineOf(text, "<spawn"));
            CHECK(contains(error.message(), "walkableAt()"));
        }
    }
    SECTION("the same area moved onto white ground is fine") {
        std::string text = smallWorld(false);
        text.replace(text.find("x=\"0\" z=\"0\""), 11, "x=\"7\" z=\"7\"");
        CrowdSimulation crowd = crowdWith(parseCrowdWorld(text, "moved.xml"), maps, testCode());
        CHECK(crowd.agents().size() == 3);
    }
}
