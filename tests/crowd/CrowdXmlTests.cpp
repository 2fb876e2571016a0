// Lab 10: loadCrowdWorld reads a whole world (an include, both kinds of
// behaviour, every condition and action) into the data the simulation runs,
// and refuses malformed files naming the file, the line and the problem.
// The same inputs, in memory, are in the fuzzers' regression corpus
// (tests/fuzz/make-regression-corpus.py, folder crowd_xml).

#include "CrowdXmlFiles.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/crowd/CrowdXml.hpp>

#include <map>
#include <string>
#include <vector>

using namespace stoa;
using namespace stoa::test;
namespace fs = std::filesystem;

namespace {


const std::string kExplorers = R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- The explorers: an FSM that searches, carries samples home and lays crumbs. -->
<agents>
  <type name="explorer" model="models/explorer.md2" skin="models/explorer.png" scale="0.05"
        speed="2" sight="6" radius="0.5" behaviour="explore"/>
  <behaviour name="explore" kind="fsm" initial="search">
    <state name="home" animation="stand" speed="0">
      <drop/>
      <stop/>
      <transition to="search"><time-in-state seconds="0.5"/></transition>
    </state>
    <state name="search" animation="run">
      <wander turn="45"/>
      <follow-crumbs/>
      <transition to="carry"><sees-sample/><not><carrying/></not></transition>
      <transition to="flee"><near type="hunter" distance="2.5"/></transition>
      <transition to="search"><blocked/></transition>
      <transition to="search"><blocked ahead="2"/><chance per-step="0.25"/></transition>
    </state>
    <state name="carry" speed="0.8">
      <seek target="sample"/>
      <pick-up/>
      <seek target="base"/>
      <drop-crumb/>
      <transition to="home"><at-base/></transition>
      <transition to="home"><at-base distance="3"/><carrying/></transition>
    </state>
    <state name="flee">
      <flee from="hunter"/>
      <seek target="crumb"/>
      <pick-up-crumb/>
      <transition to="search"><not><sees type="hunter"/></not></transition>
      <transition to="search"><message name="all-clear"/><smells-crumb/></transition>
      <transition to="home"/>
    </state>
  </behaviour>
</agents>
)";

const std::string kWorld = R"(<world seed="7" step="0.05">
  <include file="agents/explorers.xml"/>
  <ground collision="maps/collision.png" height="maps/height.png" min="-20 -10" max="20 10"
          height-min="-1" height-max="3" scenery="terrain"/>
  <base x="0" z="10" radius="2"/>
  <base x="5" z="-5"/>
  <samples count="40" x="0" z="-8" radius="6"/>
  <spawn type="explorer" count="20" x="0" z="10" radius="2" team="1"/>
  <spawn type="hunter" count="2" x="1" z="2"/>
  <type name="hunter" model="hunter.md2" skin="hunter.png" behaviour="hunt"/>
  <behaviour name="hunt" kind="subsumption">
    <layer name="chase" animation="attack" speed="1.5">
      <when><sees type="explorer"/><not><always/></not></when>
      <seek target="explorer"/>
      <attack type="explorer"/>
      <send message="all-clear" radius="6"/>
    </layer>
    <layer name="roam">
      <wander/>
      <send message="here"/>
    </layer>
  </behaviour>
</world>
)";

const std::string kAgentsStart = "<agents>\n";

} // namespace

TEST_CASE("Crowd XML: a complete world with an include reads into the expected data", "[crowd][xml]") {
    TempFolder folder("crowd-xml");
    const fs::path worldPath = folder.write("world.xml", kWorld);
    folder.write("agents/explorers.xml", kExplorers);
    const CrowdWorld world = loadCrowdWorld(worldPath);

    CHECK(world.file == worldPath);
    CHECK(world.seed == 7u);
    CHECK(world.step == 0.05f);
    CHECK(world.ground.collisionMap == folder.path() / "maps/collision.png");
    CHECK(world.ground.heightMap == folder.path() / "maps/height.png");
    CHECK(world.ground.footprintMin == glm::vec2(-20.0f, -10.0f));
    CHECK(world.ground.footprintMax == glm::vec2(20.0f, 10.0f));
    CHECK(world.ground.heightMin == -1.0f);
    CHECK(world.ground.heightMax == 3.0f);
    CHECK(world.ground.scenery == "terrain");
    CHECK(world.ground.line == 3);

    REQUIRE(world.bases.size() == 2);
    CHECK(world.bases[0].position == glm::vec2(0.0f, 10.0f));
    CHECK(world.bases[0].radius == 2.0f);
    CHECK(world.bases[1].radius == 1.5f);
    CHECK(world.bases[1].line == 6);
    REQUIRE(world.samples.size() == 1);
    CHECK(world.samples[0].count == 40);
    CHECK(world.samples[0].centre == glm::vec2(0.0f, -8.0f));
    CHECK(world.samples[0].radius == 6.0f);

    REQUIRE(world.types.size() == 2);
    const AgentType& explorer = world.types[0];
    CHECK(explorer.name == "explorer");
    CHECK(explorer.model == folder.path() / "agents/models/explorer.md2");
    CHECK(explorer.skin == folder.path() / "agents/models/explorer.png");
    CHECK(explorer.scale == 0.05f);
    CHECK(explorer.speed == 2.0f);
    CHECK(explorer.sightRadius == 6.0f);
    CHECK(explorer.radius == 0.5f);
    CHECK(explorer.line == 4);
    const AgentType& hunter = world.types[1];
    CHECK(hunter.model == folder.path() / "hunter.md2");
    CHECK(hunter.scale == 1.0f);
    CHECK(hunter.speed == 1.0f);
    CHECK(hunter.sightRadius == 5.0f);
    CHECK(hunter.radius == 0.4f);
    CHECK(world.findType("hunter") == 1);
    CHECK(world.findType("nobody") == -1);

    REQUIRE(world.behaviours.size() == 2);
    CHECK(explorer.behaviourIndex == world.findBehaviour("explore"));
    CHECK(hunter.behaviourIndex == world.findBehaviour("hunt"));
    CHECK(world.findBehaviour("explore") == 0);

    REQUIRE(world.spawns.size() == 2);
    CHECK(world.spawns[0].typeIndex == 0);
    CHECK(world.spawns[0].count == 20);
    CHECK(world.spawns[0].team == 1);
    CHECK(world.spawns[0].radius == 2.0f);
    CHECK(world.spawns[1].typeIndex == 1);
    CHECK(world.spawns[1].radius == 1.0f);
    CHECK(world.spawns[1].team == 0);
    CHECK(world.spawns[1].line == 9);

    SECTION("the FSM") {
        const Behaviour& explore = world.behaviours[0];
        CHECK(explore.kind == Behaviour::Kind::StateMachine);
        CHECK(explore.line == lineOf(kExplorers, "<behaviour name=\"explore\""));
        const std::vector<MachineState>& states = explore.machine.states;
        REQUIRE(states.size() == 4);
        CHECK(explore.machine.initial == 1);
        CHECK(states[0].name == "home");
        CHECK(states[0].animation == "stand");
        CHECK(states[0].speedScale == 0.0f);
        CHECK(states[1].animation == "run");
        CHECK(states[2].speedScale == 0.8f);
        CHECK(states[3].animation == "run");
        CHECK(states[3].speedScale == 1.0f);

        using A = Action::Kind;
        REQUIRE(states[0].actions.size() == 2);
        CHECK(states[0].actions[0].kind == A::Drop);
        CHECK(states[0].actions[1].kind == A::Stop);
        REQUIRE(states[1].actions.size() == 2);
        CHECK(states[1].actions[0].kind == A::Wander);
        CHECK(states[1].actions[0].value == 45.0f);
        CHECK(states[1].actions[0].line == lineOf(kExplorers, "<wander"));
        CHECK(states[1].actions[1].kind == A::FollowCrumbs);
        REQUIRE(states[2].actions.size() == 4);
        CHECK(states[2].actions[0].kind == A::Seek);
        CHECK(states[2].actions[0].target == "sample");
        CHECK(states[2].actions[1].kind == A::PickUp);
        CHECK(states[2].actions[2].target == "base");
        CHECK(states[2].actions[3].kind == A::DropCrumb);
        REQUIRE(states[3].actions.size() == 3);
        CHECK(states[3].actions[0].kind == A::Flee);
        CHECK(states[3].actions[0].target == "hunter");
        CHECK(states[3].actions[1].target == "crumb");
        CHECK(states[3].actions[2].kind == A::PickUpCrumb);

        using C = Condition::Kind;
        const MachineState& home = states[0];
        REQUIRE(home.transitions.size() == 1);
        CHECK(home.transitions[0].target == 1);
        CHECK(home.transitions[0].line == lineOf(kExplorers, "<transition to=\"search\"><time-in-state"));
        REQUIRE(home.transitions[0].when.size() == 1);
        CHECK(home.transitions[0].when[0].kind == C::TimeInState);
        CHECK(home.transitions[0].when[0].value == 0.5f);

        const MachineState& search = states[1];
        REQUIRE(search.transitions.size() == 4);
        CHECK(search.transitions[0].target == 2);
        REQUIRE(search.transitions[0].when.size() == 2);
        CHECK(search.transitions[0].when[0].kind == C::SeesSample);
        CHECK(!search.transitions[0].when[0].negated);
        CHECK(search.transitions[0].when[1].kind == C::Carrying);
        CHECK(search.transitions[0].when[1].negated);
        CHECK(search.transitions[1].target == 3);
        CHECK(search.transitions[1].when[0].kind == C::Near);
        CHECK(search.transitions[1].when[0].type == "hunter");
        CHECK(search.transitions[1].when[0].value == 2.5f);
        CHECK(search.transitions[2].when[0].kind == C::Blocked);
        CHECK(search.transitions[2].when[0].value == 1.0f);
        REQUIRE(search.transitions[3].when.size() == 2);
        CHECK(search.transitions[3].when[0].value == 2.0f);
        CHECK(search.transitions[3].when[1].kind == C::Chance);
        CHECK(search.transitions[3].when[1].value == 0.25f);

        const MachineState& carry = states[2];
        REQUIRE(carry.transitions.size() == 2);
        CHECK(carry.transitions[0].target == 0);
        CHECK(carry.transitions[0].when[0].kind == C::AtBase);
        CHECK(carry.transitions[0].when[0].value == 1.5f);
        CHECK(carry.transitions[1].when[0].value == 3.0f);

        const MachineState& flee = states[3];
        REQUIRE(flee.transitions.size() == 3);
        CHECK(flee.transitions[0].when[0].kind == C::Sees);
        CHECK(flee.transitions[0].when[0].negated);
        CHECK(flee.transitions[0].when[0].line == lineOf(kExplorers, "<not><sees"));
        CHECK(flee.transitions[1].when[0].kind == C::Message);
        CHECK(flee.transitions[1].when[0].type == "all-clear");
        CHECK(flee.transitions[1].when[1].kind == C::SmellsCrumb);
        CHECK(flee.transitions[2].when.empty());
        CHECK(flee.transitions[2].target == 0);
    }

    SECTION("the subsumption stack") {
        const Behaviour& hunt = world.behaviours[1];
        CHECK(hunt.kind == Behaviour::Kind::Subsumption);
        const std::vector<Layer>& layers = hunt.stack.layers;
        REQUIRE(layers.size() == 2);
        CHECK(layers[0].name == "chase");
        CHECK(layers[0].animation == "attack");
        CHECK(layers[0].speedScale == 1.5f);
        CHECK(layers[0].line == 12);
        REQUIRE(layers[0].when.size() == 2);
        CHECK(layers[0].when[0].kind == Condition::Kind::Sees);
        CHECK(layers[0].when[0].type == "explorer");
        CHECK(layers[0].when[1].kind == Condition::Kind::Always);
        CHECK(layers[0].when[1].negated);
        REQUIRE(layers[0].actions.size() == 3);
        CHECK(layers[0].actions[0].kind == Action::Kind::Seek);
        CHECK(layers[0].actions[0].target == "explorer");
        CHECK(layers[0].actions[1].kind == Action::Kind::Attack);
        CHECK(layers[0].actions[1].target == "explorer");
        CHECK(layers[0].actions[2].kind == Action::Kind::Send);
        CHECK(layers[0].actions[2].target == "all-clear");
        CHECK(layers[0].actions[2].value == 6.0f);
        CHECK(layers[1].when.empty());
        CHECK(layers[1].animation == "run");
        REQUIRE(layers[1].actions.size() == 2);
        CHECK(layers[1].actions[0].value == 90.0f);
        CHECK(layers[1].actions[1].value == 8.0f);
        CHECK(layers[1].actions[1].line == lineOf(kWorld, "<send message=\"here\""));
    }
}

TEST_CASE("Crowd XML: defaults, <not><not> and a world parsed from memory", "[crowd][xml]") {
    TempFolder folder("crowd-xml");
    folder.write("agents.xml", "<agents><type name=\"a\" model=\"a.md2\" skin=\"a.png\" behaviour=\"b\"/></agents>");
    const std::string text = "<world>\n<include file=\"agents.xml\"/>\n<ground collision=\"/abs/c.png\" height=\"\"/>\n"
                             "<behaviour name=\"b\" kind=\"subsumption\"><layer name=\"l\">"
                             "<when><not><not><carrying/></not></not></when><stop/></layer></behaviour>\n"
                             "<spawn type=\"a\" count=\"0\" x=\"0\" z=\"0\" radius=\"0\"/>\n</world>";
    const CrowdWorld world = parseCrowdWorld(text, folder / "memory.xml");
    CHECK(world.file == folder / "memory.xml");
    CHECK(world.seed == 1u);
    CHECK(world.step == 1.0f / 30.0f);
    CHECK(world.ground.collisionMap == "/abs/c.png");
    CHECK(world.ground.heightMap.empty());
    CHECK(world.ground.footprintMin == glm::vec2(-15.0f));
    CHECK(world.ground.footprintMax == glm::vec2(15.0f));
    CHECK(world.ground.scenery == "none");
    REQUIRE(world.types.size() == 1);
    CHECK(world.types[0].behaviourIndex == 0);
    REQUIRE(world.behaviours[0].stack.layers[0].when.size() == 1);
    CHECK(!world.behaviours[0].stack.layers[0].when[0].negated);
    CHECK(world.spawns[0].count == 0);
    CHECK(world.spawns[0].team == 0);
}

TEST_CASE("Crowd XML: a missing world file names the file, line 0", "[crowd][xml]") {
    TempFolder folder("crowd-xml");
    try {
        (void)loadCrowdWorld(folder / "absent.xml");
        FAIL("no InputError");
    } catch (const InputError& error) {
        CHECK(error.file() == (folder / "absent.xml").string());
        CHECK(error.line() == 0);
        CHECK(contains(error.message(), "does not exist"));
    }
}

TEST_CASE("Crowd XML: malformed worlds are refused with the file, the line and the problem", "[crowd][xml]") {
    const std::string agents = "agents.xml";
    const std::string includeAgents = "  <include file=\"agents.xml\"/>\n";

    SECTION("malformed XML") {
        expectError({{"world.xml", "<world>\n  <ground collision=\"c.png\">\n</world>\n"}}, "world.xml", "</world>",
                    "malformed XML: Start-end tags mismatch");
    }
    SECTION("an unclosed attribute") {
        expectError({{"world.xml", "<world seed=\"1>\n"}}, "world.xml", "<world", "malformed XML");
    }
    SECTION("an empty file") {
        expectError({{"world.xml", ""}}, "world.xml", "", "malformed XML: No document element found");
    }
    SECTION("the wrong root") {
        expectError({{"world.xml", "<!-- a comment -->\n<agents/>\n"}}, "world.xml", "<agents", "the root element is <agents>");
    }
    SECTION("two root elements") {
        expectError({{"world.xml", world("") + "<world/>\n"}}, "world.xml", "<world/>", "a second root element <world>");
    }
    SECTION("an unknown element") {
        expectError({{"world.xml", world("  <wall x=\"1\"/>\n")}}, "world.xml", "<wall",
                    "unknown element <wall> in <world>; expected one of: include, type, behaviour");
    }
    SECTION("an unknown attribute") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"fsm\">\n    <state name=\"s\" sped=\"2\"/>\n"
                                         "  </behaviour>\n")}},
                    "world.xml", "sped=", "unknown attribute 'sped' on <state>; expected one of: name, animation, speed");
    }
    SECTION("an unknown condition") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"subsumption\">\n    <layer name=\"l\">\n"
                                         "      <when><hungry/></when>\n    </layer>\n  </behaviour>\n")}},
                    "world.xml", "<hungry", "unknown condition <hungry>");
    }
    SECTION("text in an element") {
        expectError({{"world.xml", world("  <base x=\"0\" z=\"0\">\n   here\n  </base>\n")}}, "world.xml", "here",
                    "unexpected text 'here");
    }
    SECTION("a missing attribute") {
        expectError({{"world.xml", world("  <spawn count=\"3\" x=\"0\" z=\"0\"/>\n")}}, "world.xml", "<spawn count",
                    "missing attribute 'type' on <spawn>");
    }
    SECTION("a world without ground") {
        expectError({{"world.xml", "<world>\n  <spawn type=\"a\" count=\"1\" x=\"0\" z=\"0\"/>\n</world>\n"}}, "world.xml",
                    "<world", "no <ground>");
    }
    SECTION("a second ground") {
        expectError({{"world.xml", world("  <ground collision=\"d.png\"/>\n")}}, "world.xml", "d.png", "a second <ground>");
    }
    SECTION("not a number: a unit after it") {
        expectError({{"world.xml", world("  <type name=\"t\" model=\"m\" skin=\"s\" speed=\"1.5m\" behaviour=\"walk\"/>\n")}},
                    "world.xml", "1.5m", "the attribute speed=\"1.5m\" on <type> is not a number");
    }
    SECTION("not a number: nan") {
        expectError({{"world.xml", world("  <base x=\"nan\" z=\"0\"/>\n")}}, "world.xml", "nan", "x=\"nan\" on <base> is not a number");
    }
    SECTION("not a number: inf") {
        expectError({{"world.xml", world("  <base x=\"0\" z=\"inf\"/>\n")}}, "world.xml", "inf", "is not a number");
    }
    SECTION("not a number: empty") {
        expectError({{"world.xml", world("  <base x=\"\" z=\"0\"/>\n")}}, "world.xml", "<base", "x=\"\" on <base> is not a number");
    }
    SECTION("not a pair of numbers") {
        expectError({{"world.xml", "<world>\n  <ground collision=\"c.png\"\n    min=\"1 2 3\"/>\n</world>\n"}}, "world.xml",
                    "<ground", "min=\"1 2 3\" on <ground> is not a pair of numbers");
    }
    SECTION("a count that is not whole") {
        expectError({{"world.xml", world("  <samples count=\"1.5\" x=\"0\" z=\"0\"/>\n")}}, "world.xml", "<samples",
                    "is not a whole number");
    }
    SECTION("out of range: chance") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"subsumption\">\n    <layer name=\"l\">\n"
                                         "      <when><chance per-step=\"1.5\"/></when>\n    </layer>\n  </behaviour>\n")}},
                    "world.xml", "<when><chance", "per-step=\"1.5\" on <chance> is out of range: it must be between 0 and 1");
    }
    SECTION("out of range: step") {
        expectError({{"world.xml", "<world step=\"0\">\n</world>\n"}}, "world.xml", "<world", "step=\"0\" on <world> is out of range");
    }
    SECTION("out of range: seed") {
        expectError({{"world.xml", "<world seed=\"4294967296\">\n</world>\n"}}, "world.xml", "<world", "seed=\"4294967296\"");
    }
    SECTION("ground min not below max") {
        expectError({{"world.xml", "<world>\n  <ground collision=\"c.png\" min=\"5 0\" max=\"5 9\"/>\n</world>\n"}}, "world.xml",
                    "<ground", "min must be less than max");
    }
    SECTION("an unknown state in a transition") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"fsm\">\n    <state name=\"s\">\n"
                                         "      <transition to=\"sleep\"/>\n    </state>\n  </behaviour>\n")}},
                    "world.xml", "<transition", "to=\"sleep\" names no state of the behaviour 'b'; its states are: s");
    }
    SECTION("an unknown initial state") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"fsm\" initial=\"x\">\n    <state name=\"s\"/>\n"
                                         "  </behaviour>\n")}},
                    "world.xml", "initial=", "initial=\"x\" names no state");
    }
    SECTION("a behaviour without states") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"fsm\">\n  </behaviour>\n")}}, "world.xml",
                    "name=\"b\"", "has no <state>");
    }
    SECTION("a <not> with two conditions") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"subsumption\">\n    <layer name=\"l\"><when>\n"
                                         "      <not><carrying/><always/></not>\n    </when></layer>\n  </behaviour>\n")}},
                    "world.xml", "<not>", "<not> holds exactly one condition; found 2");
    }
    SECTION("an unknown behaviour in a type") {
        expectError({{"world.xml", world("  <type name=\"t\" model=\"m\" skin=\"s\" behaviour=\"dance\"/>\n")}}, "world.xml",
                    "dance", "the type 't' has behaviour=\"dance\", which is not defined; behaviours: walk");
    }
    SECTION("an unknown type in a spawn") {
        expectError({{"world.xml", world("  <spawn type=\"ghost\" count=\"1\" x=\"0\" z=\"0\"/>\n")}}, "world.xml", "ghost",
                    "<spawn> names the type 'ghost', which is not defined; types: walker");
    }
    SECTION("an unknown type in a condition") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"fsm\">\n    <state name=\"s\">\n"
                                         "      <transition to=\"s\"><not><near type=\"ghost\" distance=\"1\"/></not></transition>\n"
                                         "    </state>\n  </behaviour>\n")}},
                    "world.xml", "ghost", "<near> names the type 'ghost', which is not defined");
    }
    SECTION("a team with no base") {
        expectError({{"world.xml", world("  <base x=\"0\" z=\"0\"/>\n  <spawn type=\"walker\" count=\"1\" x=\"0\" z=\"0\" team=\"1\"/>\n")}},
                    "world.xml", "team=", "team=\"1\" names no base; the world has 1 (teams 0 to 0)");
    }
    SECTION("a type defined twice, in an included file") {
        expectError({{"world.xml", world(includeAgents)},
                     {agents, kAgentsStart + "  <type name=\"walker\" model=\"m\" skin=\"s\" behaviour=\"walk\"/>\n</agents>\n"}},
                    agents, "<type", "the type 'walker' is defined twice; the first is at ");
    }
    SECTION("a behaviour defined twice") {
        expectError({{"world.xml", world("  <behaviour name=\"walk\" kind=\"subsumption\"><layer name=\"l\"/></behaviour>\n")}},
                    "world.xml", "name=\"walk\" kind=\"subsumption\"", "the behaviour 'walk' is defined twice");
    }
    SECTION("a state defined twice") {
        expectError({{"world.xml", world("  <behaviour name=\"b\" kind=\"fsm\">\n    <state name=\"s\"/>\n"
                                         "    <state name=\"s\"/>\n  </behaviour>\n")}},
                    "world.xml", "<state name=\"s\"/>\n  </", "the state 's' is defined twice");
    }
    SECTION("an include loop") {
        expectError({{"world.xml", world(includeAgents)},
                     {agents, kAgentsStart + "  <include file=\"more/b.xml\"/>\n</agents>\n"},
                     {"more/b.xml", "<agents>\n\n  <include file=\"../agents.xml\"/>\n</agents>\n"}},
                    "more/b.xml", "<include", "include loop: ");
    }
    SECTION("an include of itself") {
        expectError({{"world.xml", world("  <include file=\"world.xml\"/>\n")}}, "world.xml", "<include", "include loop: ");
    }
    SECTION("a missing include file") {
        expectError({{"world.xml", world("  <include file=\"missing.xml\"/>\n")}}, "world.xml", "missing.xml",
                    "<include> file=\"missing.xml\" cannot be read: the file does not exist");
    }
    SECTION("an included file with the wrong root") {
        expectError({{"world.xml", world(includeAgents)}, {agents, "\n<world/>\n"}}, agents, "<world",
                    "the root element of an included file is <world>; expected <agents>");
    }
    SECTION("includes nested too deep") {
        std::map<std::string, std::string> files{{"world.xml", world("  <include file=\"a1.xml\"/>\n")}};
        for (int i = 1; i <= CrowdXmlLimits::maxIncludeDepth; ++i) {
            files["a" + std::to_string(i) + ".xml"] = "<agents>\n  <include file=\"a" + std::to_string(i + 1) + ".xml\"/>\n</agents>\n";
        }
        files["a9.xml"] = "<agents/>\n";
        expectError(files, "a8.xml", "<include", "<include> nests deeper than 8 files");
    }
    SECTION("an error inside an included file names that file") {
        expectError({{"world.xml", world(includeAgents)},
                     {agents, kAgentsStart + "  <behaviour name=\"x\" kind=\"fsm\">\n    <state name=\"s\">\n"
                                             "      <seek targt=\"base\"/>\n    </state>\n  </behaviour>\n</agents>\n"}},
                    agents, "targt", "unknown attribute 'targt' on <seek>; expected one of: target");
    }
    SECTION("malformed XML in an included file names that file") {
        expectError({{"world.xml", world(includeAgents)}, {agents, "<agents>\n\n  <type name=\"a\"\n</agents>\n"}}, agents,
                    "</agents>", "malformed XML");
    }
    SECTION("too many agents") {
        expectError({{"world.xml", world("  <spawn type=\"walker\" count=\"60000\" x=\"0\" z=\"0\"/>\n"
                                         "  <spawn type=\"walker\" count=\"40000\" x=\"0\" z=\"0\"/>\n")}},
                    "world.xml", "count=\"3\"", "place 100003 agents in all; at most 100000 are allowed (100,000 agents step in about");
    }
    SECTION("too many samples in one element") {
        expectError({{"world.xml", world("  <samples count=\"100001\" x=\"0\" z=\"0\"/>\n")}}, "world.xml", "<samples",
                    "count=\"100001\" on <samples> is out of range: it must be 0 to 100000");
    }
}

TEST_CASE("Crowd XML: a hostile file of 4 MB reads in linear time and memory", "[crowd][xml]") {
    const std::string head = "<world><ground collision=\"c\"/><type name=\"a\" model=\"m\" skin=\"s\" behaviour=\"b\"/>"
                             "<spawn type=\"a\" count=\"1\" x=\"0\" z=\"0\"/>\n";
    SECTION("a behaviour of 75,000 states, each with a transition") {
        std::string text = head + "<behaviour name=\"b\" kind=\"fsm\">";
        const int states = 75000;
        for (int i = 0; i < states; ++i) {
            text += "<state name=\"s" + std::to_string(i) + "\"><transition to=\"s" + std::to_string(i * 7 % states) +
                    "\"/></state>";
        }
        text += "</behaviour></world>";
        const CrowdWorld world = parseCrowdWorld(text, "states.xml");
        REQUIRE(world.behaviours[0].machine.states.size() == std::size_t(states));
        CHECK(world.behaviours[0].machine.states[3].transitions[0].target == 21);
    }
    SECTION("370,000 nested <not> elements (a loop, not recursion: no stack overflow)") {
        const int depth = 370000;
        std::string text = head + "<behaviour name=\"b\" kind=\"subsumption\"><layer name=\"l\"><when>";
        for (int i = 0; i < depth; ++i) text += "<not>";
        text += "<carrying/>";
        for (int i = 0; i < depth; ++i) text += "</not>";
        text += "</when></layer></behaviour></world>";
        REQUIRE(text.size() <= CrowdXmlLimits::maxFileBytes);
        const CrowdWorld world = parseCrowdWorld(text, "nots.xml");
        CHECK(world.behaviours[0].stack.layers[0].when[0].kind == Condition::Kind::Carrying);
        CHECK(!world.behaviours[0].stack.layers[0].when[0].negated);  // an even number of <not>
    }
    SECTION("a message lists a dozen names, then how many more") {
        std::string text = head + "<behaviour name=\"b\" kind=\"fsm\">";
        for (int i = 0; i < 50; ++i) text += "<state name=\"s" + std::to_string(i) + "\"/>";
        text += "<state name=\"x\"><transition to=\"nope\"/></state></behaviour></world>";
        try {
            (void)parseCrowdWorld(text, "names.xml");
            FAIL("no InputError");
        } catch (const InputError& error) {
            CHECK(contains(error.message(), "its states are: s0, s1, s2, s3, s4, s5, s6, s7, s8, s9, s10, s11 and 39 more"));
        }
    }
}
