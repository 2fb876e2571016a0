#pragma once
// A crowd of agents over a ground (lab 10), stepped at a fixed rate. Each step
// every living agent, cell by cell of a grid over the ground (seeing the others
// where they stood when the step began):
//   1. senses (CrowdSenses, answered lazily: only the conditions its behaviour asks);
//   2. picks its actions: stepStateMachine() or arbitrateLayers() (the student's);
//   3. runs them: they set where it heads and how fast, pick up, drop, attack, send;
//   4. moves along its heading, turning away where walkableAt() (the student's)
//      says the ground ahead is blocked, and stands at heightAt() (the student's).
// Randomness comes from a hash of (seed, agent, step, the XML line asking), never
// from a sequence, so the order in which conditions are tested cannot change a
// run: the same world gives the same crowd on every machine. Heights never feed
// back into the motion. No OpenGL here.
//
//   CrowdSimulation crowd(world, loadGroundMaps(world.ground, world.file));
//   crowd.advance(300);   // ten seconds at 30 steps per second

#include <stoa/core/StudentCode.hpp>
#include <stoa/crowd/CrowdLab.hpp>
#include <stoa/crowd/CrowdWorld.hpp>
#include <stoa/crowd/GroundMaps.hpp>

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace stoa {

struct CrowdAgent {
    int type = 0;                 // index into CrowdWorld::types
    int team = 0;                 // index into CrowdWorld::bases (0 when there are none)
    int spawn = 0;                // index into CrowdWorld::spawns
    glm::vec2 position{0.0f};     // x, z in metres
    float y = 0.0f;               // heightAt(position)
    float heading = 0.0f;         // radians; 0 faces +z, pi/2 faces +x
    float speed = 0.0f;           // metres per second this step
    int state = 0;                // the FSM state, or the layer that ran (-1: none)
    float timeInState = 0.0f;     // seconds
    float animationTime = 0.0f;   // seconds into the current animation
    std::string animation = "stand";   // the MD2 animation its state or layer plays
    bool carrying = false;
    bool alive = true;
    float deadFor = 0.0f;         // seconds since it was attacked (it comes back after respawnSeconds)
    float walkedSinceCrumb = 0.0f;
    std::uint32_t messages = 0;   // bit i: message i arrived this step
    std::uint32_t nextMessages = 0;
};

struct CrowdStatistics {
    int living = 0;
    int carrying = 0;
    int samplesOnGround = 0;
    int delivered = 0;
    int crumbs = 0;
    int attacks = 0;
    int blockedMoves = 0;   // moves the collision map turned aside
};

class CrowdSimulation {
public:
    static constexpr float reach = 1.0f;            // metres beyond the agent's radius for pick-up and attack
    static constexpr float crumbSpacing = 1.0f;     // metres walked between two crumbs
    static constexpr int maxCrumbs = 20000;
    static constexpr float respawnSeconds = 8.0f;
    static constexpr int trailLength = 48;          // positions kept per agent
    static constexpr int trailEvery = 6;            // steps between two trail positions

    /// Places the agents and samples (seeded, on walkable ground) and runs no
    /// step. Throws InputError naming the world file and a <spawn> or
    /// <samples> line when no walkable point is found in its area.
    CrowdSimulation(const CrowdWorld& world, GroundMaps maps);

    void step();
    void advance(int steps);

    const CrowdWorld& world() const { return m_world; }
    const GroundMaps& maps() const { return m_maps; }
    const CrowdFunctions& code() const { return m_code; }
    const std::vector<CrowdAgent>& agents() const { return m_agents; }
    const std::vector<glm::vec2>& samples() const { return m_samples; }   // on the ground
    const std::vector<glm::vec2>& crumbs() const { return m_crumbs; }
    /// Agent i's last trailLength positions, oldest first.
    std::vector<glm::vec2> trail(std::size_t agent) const;
    CrowdStatistics statistics() const;
    long long stepCount() const { return m_step; }
    float seconds() const { return static_cast<float>(m_step) * m_world.step; }
    /// The name of the state or layer agent i is in ("" when none).
    std::string stateName(std::size_t agent) const;

    /// A random number in [0, 1) for (agent, this step, salt): the same
    /// however often and in whichever order it is asked.
    float randomFor(std::size_t agent, std::uint32_t salt) const;

    /// The index of a message name, or -1 (at most 32 names per world).
    int messageIndex(const std::string& name) const;

private:
    class Senses;
    friend class Senses;

    void placeAgents();
    void placeSamples();
    glm::vec2 randomWalkablePoint(glm::vec2 centre, float radius, std::uint32_t salt, const std::string& what,
                                  int line);
    /// An agent in the grid, where it stood when the step began.
    struct GridEntry {
        glm::vec2 position;
        int type;
        int agent;
    };

    static constexpr std::size_t kPrefetchAhead = 4;   // agents between a prefetch and its use

    void resolveNames();
    void prefetchMaps(glm::vec2 xz) const;
    void rebuildAgentGrid();
    void runAction(std::size_t index, const Action& action, float speedScale);
    void move(std::size_t index);
    int nearestAgentOfType(std::size_t index, int type, float radius) const;
    /// Calls visit(entry) for every grid entry within `radius` of `from`.
    template <typename Visit>
    void forEachNear(glm::vec2 from, float radius, Visit&& visit) const;
    int nearestPoint(const std::vector<glm::vec2>& points, glm::vec2 from, float radius) const;
    void headTowards(CrowdAgent& agent, glm::vec2 target);

    CrowdWorld m_world;
    GroundMaps m_maps;
    CrowdFunctions m_code;   // the student's, as the table held them when the crowd was made
    std::vector<CrowdAgent> m_agents;
    std::vector<glm::vec2> m_samples;
    std::vector<glm::vec2> m_crumbs;
    std::vector<glm::vec2> m_trails;      // trailLength per agent, a ring
    int m_trailCount = 0;                 // positions recorded per agent so far
    std::vector<std::string> m_messages;
    long long m_step = 0;
    int m_delivered = 0;
    int m_attacks = 0;
    int m_blockedMoves = 0;
    std::vector<const Action*> m_actions;

    // The living agents bucketed in square cells, rebuilt after each step:
    // the senses see the others where they stood when the step began, and
    // the step visits the living in this order.
    float m_cellSize = 4.0f;
    int m_cellsX = 1, m_cellsZ = 1;
    std::vector<int> m_cellStart;         // m_cellsX * m_cellsZ + 1 offsets into m_cellAgents
    std::vector<GridEntry> m_cellAgents;
    std::vector<int> m_cellOf;            // per agent, scratch of rebuildAgentGrid()
};

} // namespace stoa
