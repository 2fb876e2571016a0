#pragma once
// A crowd world as data (lab 10 and stoa-crowds): the agent types, their
// behaviours (a finite state machine or subsumption layers), the ground maps
// and where the agents start. loadCrowdWorld() (CrowdXml.hpp) reads it from
// XML; docs/crowds-xml.md is the format's reference. No OpenGL here.
//
//   world.xml --loadCrowdWorld--> CrowdWorld --CrowdSimulation--> agents each step
//
// Every element keeps the line of the XML file it came from (`line`), so that
// the simulation can name it in a message too.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace stoa {

/// A test on what an agent senses this step. CrowdSenses::holds() answers it.
struct Condition {
    enum class Kind {
        Always,        // always true
        Sees,          // an agent of type `type` within the agent's sight radius
        Near,          // an agent of type `type` within `value` metres
        Carrying,      // the agent carries a sample
        AtBase,        // within `value` metres of its team's base
        SeesSample,    // a sample on the ground within the sight radius
        SmellsCrumb,   // a crumb within the sight radius
        Blocked,       // the collision map blocks the ground `value` metres ahead
        TimeInState,   // at least `value` seconds in the current state or layer
        Message,       // a message named `type` arrived this step
        Chance,        // true with probability `value` per step (the world's seeded random)
    };
    Kind kind = Kind::Always;
    std::string type;       // Sees, Near: an agent type's name; Message: the message's name
    float value = 0.0f;     // Near, AtBase, Blocked, TimeInState, Chance (see above)
    bool negated = false;   // <not>: holds when the test fails
    int line = 0;
    int index = -1;         // set by CrowdSimulation: the index of the type (Sees, Near) or message (Message) named;
                            // Chance: where the step keeps its number, drawn as the agent's step begins (-1: drawn when asked)
};

/// Something an agent does during a step, in the order its state or layer lists them.
struct Action {
    enum class Kind {
        Wander,        // keep heading, turning by up to `value` degrees per second at random
        Seek,          // head for `target`: "base", "sample", "crumb" or an agent type's name
        Flee,          // head away from the nearest agent of type `target`
        FollowCrumbs,  // head for the crumb farthest from the base within sight
        PickUp,        // pick up the nearest sample within reach (1 m), if not carrying
        Drop,          // drop the carried sample (at the base: it counts as delivered)
        DropCrumb,     // leave a crumb here (at most one per metre walked)
        PickUpCrumb,   // remove the nearest crumb within reach
        Stop,          // stand still this step
        Send,          // send message `target` to every agent within `value` metres
        Attack,        // remove the nearest agent of type `target` within reach (1 m)
    };
    Kind kind = Kind::Stop;
    std::string target;
    float value = 0.0f;
    int line = 0;
    /// Set by CrowdSimulation: the index of the type (Seek an agent, Flee,
    /// Attack) or message (Send) named; Seek also kSeekBase, kSeekSample, kSeekCrumb;
    /// Wander: where the step keeps its number, drawn as the agent's step begins (-1: drawn when asked).
    int index = -1;
    static constexpr int kSeekBase = -2, kSeekSample = -3, kSeekCrumb = -4;
};

/// A transition fires when every one of its conditions holds (an empty list always holds).
struct Transition {
    std::vector<Condition> when;
    int target = 0;     // index into StateMachine::states
    int line = 0;
};

struct MachineState {
    std::string name;
    std::string animation;      // the MD2 animation played in this state ("run", "stand", ...)
    int animationIndex = 0;     // its index among CrowdSimulation::animationName()'s (set by the simulation)
    float speedScale = 1.0f;    // times the agent type's speed
    std::vector<Action> actions;
    std::vector<Transition> transitions;   // tried in this order; the first that holds fires
    int line = 0;
};

struct StateMachine {
    std::vector<MachineState> states;
    int initial = 0;
};

/// One layer of a subsumption architecture: it fires when all its conditions
/// hold (a layer without any always fires) and then suppresses the layers below.
struct Layer {
    std::string name;
    std::string animation;
    int animationIndex = 0;     // as MachineState's
    float speedScale = 1.0f;
    std::vector<Condition> when;
    std::vector<Action> actions;
    int line = 0;
};

/// Layers from the highest priority (first in the file) to the lowest.
struct SubsumptionStack {
    std::vector<Layer> layers;
};

struct Behaviour {
    enum class Kind { StateMachine, Subsumption };
    std::string name;
    Kind kind = Kind::StateMachine;
    StateMachine machine;        // Kind::StateMachine
    SubsumptionStack stack;      // Kind::Subsumption
    int line = 0;
};

struct AgentType {
    std::string name;
    std::filesystem::path model;    // an MD2 file
    std::filesystem::path skin;     // its texture
    float scale = 1.0f;             // model units to metres
    float speed = 1.0f;             // metres per second at speedScale 1
    float sightRadius = 5.0f;       // metres
    float radius = 0.4f;            // metres, for reach and spacing
    std::string behaviour;          // a Behaviour's name
    int behaviourIndex = -1;        // index into CrowdWorld::behaviours, set by the loader
    std::filesystem::path file;     // the XML file that defines it (the world's or an include)
    int line = 0;
};

/// `count` agents of a type, placed at random on walkable ground within
/// `radius` metres of `centre` (x, z).
struct SpawnArea {
    std::string type;
    int typeIndex = -1;
    int count = 0;
    glm::vec2 centre{0.0f};
    float radius = 1.0f;
    int team = 0;                   // which base the agents deliver to
    int line = 0;
};

/// A base: where a team's samples are delivered.
struct Base {
    glm::vec2 position{0.0f};
    float radius = 1.5f;
    int line = 0;
};

/// Samples lying on walkable ground at the start, within `radius` of `centre`.
struct SampleArea {
    int count = 0;
    glm::vec2 centre{0.0f};
    float radius = 1.0f;
    int line = 0;
};

/// The ground: maps over the footprint [min, max] (x, z) in metres. The
/// collision map is walkable where white (a grey value >= 128); the height
/// map's grey value g (8 or 16 bits) stands heightMin + (heightMax - heightMin) * g / gMax
/// metres tall. Row 0 of both images lies at z = footprintMin.y, column 0 at x = footprintMin.x.
struct GroundDescription {
    std::filesystem::path collisionMap;
    std::filesystem::path heightMap;     // empty: flat ground at heightMin
    glm::vec2 footprintMin{-15.0f};
    glm::vec2 footprintMax{15.0f};
    float heightMin = 0.0f;
    float heightMax = 0.0f;
    std::string scenery;   // "acropolis" (the lab 05 scene on the ground), "terrain" (the height map as a mesh) or "none"
    int line = 0;
};

struct CrowdWorld {
    std::filesystem::path file;            // the world file this came from
    std::uint32_t seed = 1;
    float step = 1.0f / 30.0f;             // seconds per fixed simulation step
    GroundDescription ground;
    std::vector<AgentType> types;
    std::vector<Behaviour> behaviours;
    std::vector<SpawnArea> spawns;
    std::vector<Base> bases;
    std::vector<SampleArea> samples;

    /// Index of the type or behaviour with that name, or -1.
    int findType(const std::string& name) const;
    int findBehaviour(const std::string& name) const;
};

} // namespace stoa
