// Lab 10: that a crowd is a function of its world and seed alone
// (stoa/crowd/CrowdSimulation.hpp), on the example worlds and on small worlds
// written here, with the lab code of CrowdTestCode.hpp. Checked:
//   - the same world and seed give bit-identical agents, samples and crumbs
//     after 500 steps in two runs; another seed gives other agents;
//   - the parallel step (setThreads(2), setThreads(3)) gives the serial crowd
//     bit for bit, every 50 steps of 300, in a crowd dense enough for kills
//     and in the explorers' world (which steps on one thread);
//   - every <chance> and <wander> draws randomFor(agent, its salt), the
//     numbers drawn as a step begins and those drawn when asked alike.

#include "CrowdTestCode.hpp"

#include <stoa/crowd/CrowdSimulation.hpp>
#include <stoa/crowd/CrowdXml.hpp>

#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace stoa;
using namespace stoa::crowdtest;

TEST_CASE("Crowd: the same world and seed give bit-identical agents after 500 steps", "[crowd][simulation]") {
    for (const char* name : {"mars_explorers.xml", "predators_prey.xml"}) {
        INFO(name);
        const Example e = example(name);
        CrowdSimulation first = crowdWith(e.world, e.maps, testCode());
        CrowdSimulation second = crowdWith(e.world, e.maps, testCode());
        first.advance(500);
        for (int i = 0; i < 500; ++i) second.step();
        REQUIRE(first.stepCount() == 500);
        requireIdentical(first, second);
    }
}

TEST_CASE("Crowd: the parallel step gives the serial crowd bit for bit", "[crowd][simulation][parallel]") {
    // The predators and prey ten times as many, the wolves placed among the
    // goats, so that in 300 steps wolves kill goats stepped on other threads,
    // goats bleat to goats across them, and seekers read positions the step
    // has changed; then the explorers, whose samples and crumbs keep them on one thread.
    Example dense = example("predators_prey.xml");
    for (SpawnArea& area : dense.world.spawns) {
        area.count *= 10;
        area.centre = dense.world.spawns.front().centre;
        area.radius = dense.world.spawns.front().radius;
    }
    const Example explorers = example("mars_explorers.xml");
    for (const Example* e : {static_cast<const Example*>(&dense), &explorers}) {
        for (const int threads : {2, 3}) {
            INFO(e->world.file.filename().string() << " on " << threads << " threads");
            CrowdSimulation serial = crowdWith(e->world, e->maps, testCode());
            CrowdSimulation parallel = crowdWith(e->world, e->maps, testCode());
            parallel.setThreads(threads, 0);
            REQUIRE(parallel.threads() == threads);
            for (int round = 0; round < 6; ++round) {
                serial.advance(50);
                parallel.advance(50);
                INFO("after " << serial.stepCount() << " steps");
                requireIdentical(serial, parallel);
            }
            if (e == &dense) CHECK(serial.statistics().attacks > 10);
        }
    }
}

TEST_CASE("Crowd: another seed gives other agents", "[crowd][simulation]") {
    for (const char* name : {"mars_explorers.xml", "predators_prey.xml"}) {
        INFO(name);
        Example e = example(name);
        CrowdSimulation first = crowdWith(e.world, e.maps, testCode());
        e.world.seed += 1;
        CrowdSimulation second = crowdWith(e.world, e.maps, testCode());
        first.advance(100);
        second.advance(100);
        int differ = 0;
        for (std::size_t i = 0; i < first.agents().size(); ++i)
            differ += !sameBits(first.agents()[i].position, second.agents()[i].position);
        CHECK(differ > static_cast<int>(first.agents().size()) / 2);
    }
}

TEST_CASE("Crowd: every <chance> and <wander> draws randomFor(agent, its line's salt), however many a behaviour has",
          "[crowd][simulation]") {
    // The step draws a behaviour's first four numbers (its chances, then its
    // wanders) as an agent's step begins, the rest when asked: each must be
    // the number randomFor() gives, whichever way it was drawn.
    const GroundMaps maps = flatGround({-10.0f, -10.0f}, {10.0f, 10.0f}, 20);
    const auto world = [](const std::string& layers) {
        return "<world seed=\"7\">\n"
               "  <ground collision=\"c.png\" min=\"-10 -10\" max=\"10 10\"/>\n"
               "  <type name=\"walker\" model=\"w.md2\" skin=\"w.png\" behaviour=\"walk\"/>\n"
               "  <behaviour name=\"walk\" kind=\"subsumption\">\n" +
               layers +
               "  </behaviour>\n"
               "  <spawn type=\"walker\" count=\"6\" x=\"0\" z=\"0\" radius=\"2\"/>\n"
               "</world>\n";
    };
    SECTION("five chances: four drawn as the step begins, the fifth when asked") {
        std::string layers;
        for (int k = 0; k < 5; ++k)
            layers += "    <layer name=\"c" + std::to_string(k) + "\"><when><chance per-step=\"0.3\"/></when><stop/></layer>\n";
        layers += "    <layer name=\"rest\"><stop/></layer>\n";
        const std::string text = world(layers);
        CrowdSimulation crowd = crowdWith(parseCrowdWorld(text, "chances.xml"), maps, testCode());
        const int firstLine = lineOf(text, "name=\"c0\"");
        int fifthFired = 0;
        for (int step = 0; step < 200; ++step) {
            std::vector<int> expected;
            for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
                int layer = 5;
                for (int k = 0; k < 5 && layer == 5; ++k)
                    if (crowd.randomFor(i, static_cast<std::uint32_t>(firstLine + k) * 2u + 1u) < 0.3f) layer = k;
                expected.push_back(layer);
            }
            crowd.step();
            for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
                INFO("step " << step << ", agent " << i);
                REQUIRE(crowd.agents()[i].state == expected[i]);
                fifthFired += expected[i] == 4 ? 1 : 0;
            }
        }
        CHECK(fifthFired > 0);   // the number drawn when asked was asked for and decided
    }
    SECTION("a chance and two wanders, all drawn as the step begins") {
        const std::string text = world("    <layer name=\"fast\"><when><chance per-step=\"0.5\"/></when><wander turn=\"90\"/></layer>\n"
                                       "    <layer name=\"slow\"><wander turn=\"30\"/></layer>\n");
        CrowdSimulation crowd = crowdWith(parseCrowdWorld(text, "wanders.xml"), maps, testCode());
        const int fastLine = lineOf(text, "name=\"fast\""), slowLine = lineOf(text, "name=\"slow\"");
        const float step = crowd.world().step;
        const float twoPi = 6.283185307f;
        for (int n = 0; n < 60; ++n) {
            std::vector<float> expected;
            for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
                const bool fast = crowd.randomFor(i, static_cast<std::uint32_t>(fastLine) * 2u + 1u) < 0.5f;
                const int line = fast ? fastLine : slowLine;
                const float turn = glm::radians(fast ? 90.0f : 30.0f) * step;
                const float random = crowd.randomFor(i, static_cast<std::uint32_t>(line) * 2u);
                expected.push_back(crowd.agents()[i].heading + (2.0f * random - 1.0f) * turn);
            }
            crowd.step();
            for (std::size_t i = 0; i < crowd.agents().size(); ++i) {
                INFO("step " << n << ", agent " << i);
                float d = crowd.agents()[i].heading - expected[i];
                d -= twoPi * std::round(d / twoPi);   // headings are kept in [-pi, pi)
                REQUIRE(std::fabs(d) < 1e-4f);
            }
        }
    }
}
