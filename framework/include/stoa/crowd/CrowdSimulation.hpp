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

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace stoa {

class StepWorkers;

/// One agent: 64 bytes on a 64-byte boundary, so the step reads one cache
/// line an agent (a world has at most 32,767 types, bases and animations).
struct alignas(64) CrowdAgent {
    std::int16_t type = 0;        // index into CrowdWorld::types
    std::int16_t team = 0;        // index into CrowdWorld::bases (0 when there are none)
    int spawn = 0;                // index into CrowdWorld::spawns
    glm::vec2 position{0.0f};     // x, z in metres
    float y = 0.0f;               // heightAt(position)
    float heading = 0.0f;         // radians; 0 faces +z, pi/2 faces +x
    float speed = 0.0f;           // metres per second this step
    int state = 0;                // the FSM state, or the layer that ran (-1: none)
    float timeInState = 0.0f;     // seconds
    float animationTime = 0.0f;   // seconds into the current animation
    std::int16_t animation = 0;   // the MD2 animation its state or layer plays: CrowdSimulation::animationName(animation)
    bool carrying = false;
    bool alive = true;
    float deadFor = 0.0f;         // seconds since it was attacked (it comes back after respawnSeconds)
    float walkedSinceCrumb = 0.0f;
    std::uint32_t messages = 0;   // bit i: message i, sent to it in the step before, heard in this one
                                  // (between steps: sent in the step that ended, heard in the next)
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
    ~CrowdSimulation();
    CrowdSimulation(CrowdSimulation&&) noexcept;
    CrowdSimulation& operator=(CrowdSimulation&&) noexcept;

    /// Steps on `threads` threads from now on (1, the default: on the caller's
    /// alone). Any count gives the same crowd bit for bit: the others step
    /// each agent ahead of its turn, and the caller takes each result in the
    /// serial order, stepping again in its turn an agent whose result a kill
    /// or a move earlier in the step changed. Worlds with samples or crumbs
    /// (shared lists each agent's turn changes) step on one thread whatever this says,
    /// and so does a step of fewer than `fromAgents` living agents (handing
    /// work to threads costs more than such a step: 0 to step all in parallel).
    void setThreads(int threads, int fromAgents = 2000);
    int threads() const;

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

    /// The name of animation `index` (CrowdAgent::animation); 0 is "stand".
    const std::string& animationName(int index) const { return m_animations[static_cast<std::size_t>(index)]; }

private:
    class Senses;
    friend class Senses;
    struct Outcome;
    struct StepScratch;

    /// An agent in the grid, where it stood when the step began (16 bytes:
    /// four to a cache line).
    struct GridEntry {
        glm::vec2 position;
        float heading;
        int agent;
    };

    static constexpr std::size_t kPrefetchAhead = 6;   // agents between a prefetch and its use

    void placeAgents();
    void placeSamples();
    glm::vec2 randomWalkablePoint(glm::vec2 centre, float radius, std::uint32_t salt, const std::string& what,
                                  int line);
    void resolveNames();
    /// Gives the behaviour's chances and wanders their slots in StepScratch::drawn (m_drawnSalts).
    void drawAtStepStart(Behaviour& behaviour);
    /// The lab's look-ups and layers as plain functions, where they are (m_walkableAt ...).
    void takeDirectCalls();
    void measureReaches();
    void rebuildAgentGrid();
    void stepTheDead();
    void endStep();

    // One living agent's step (CrowdAgentStep.cpp), on `agent`, which is
    // m_agents[index]: in the parallel step's first pass scratch.outcome
    // records what it does to the others instead of doing it.
    void stepAgent(std::size_t index, CrowdAgent& agent, StepScratch& scratch);
    void runAction(std::size_t index, CrowdAgent& agent, const Action& action, float speedScale,
                   StepScratch& scratch);
    /// Every action but <stop> and <wander>, which runAction() does itself (most agents' every step).
    void runOtherAction(std::size_t index, CrowdAgent& agent, const Action& action, float speedScale,
                        StepScratch& scratch);
    void move(CrowdAgent& agent, StepScratch& scratch);
    /// Where a <seek> heads the agent (false: nothing of the kind in sight).
    bool seekTarget(std::size_t index, const CrowdAgent& agent, const Action& action, StepScratch& scratch,
                    glm::vec2& target) const;
    /// <pick-up>, <drop>, <drop-crumb>, <pick-up-crumb>: the samples and crumbs all agents share (serial step only).
    void runSharedListAction(CrowdAgent& agent, const Action& action);
    /// Heads the agent at the crumb within sight farthest from its base.
    void followCrumbs(CrowdAgent& agent) const;
    /// The position of agent `found` as the agent stepping reads it (recorded in the parallel pass).
    glm::vec2 targetPosition(int found, StepScratch& scratch) const;
    /// Starts loading what the agent at `place` in the step order will read.
    void prefetchPlace(std::size_t place) const;
    /// direction(heading), remembered: the agent's heading from the last step, the turns of this one.
    static glm::vec2 headingDirection(StepScratch& scratch, float heading);
    /// randomFor(agent, salt) is randomFrom(randomBase(agent), salt): the base once per agent and step.
    std::uint32_t randomBase(std::size_t agent) const;
    static float randomFrom(std::uint32_t base, std::uint32_t salt);
    /// randomFor(agent, salt) for the agent stepping: drawn as its step began
    /// where `drawn` (a Condition's or Action's index) is a slot, else now.
    static float randomOf(const StepScratch& scratch, int drawn, std::uint32_t salt);
    /// Where an agent in the grid stood when the step began.
    glm::vec2 startPosition(std::size_t agent) const {
        return m_cellAgents[static_cast<std::size_t>(m_places[agent])].position;
    }
    void kill(std::size_t victim);
    bool walkable(glm::vec2 xz) const;
    /// walkable(point) for <blocked ahead> of agent `index`, remembered (m_memos).
    bool walkableAhead(std::size_t index, glm::vec2 point) const;
    float height(glm::vec2 xz) const;
    /// The nearest living agent of `type` within `radius` of `from` (not `index`), ties to the lower index; -1 if none.
    int nearestAgentOfType(std::size_t index, glm::vec2 from, int type, float radius) const;
    /// Whether there is one (the same as nearestAgentOfType() >= 0, stopping at the first).
    bool anyAgentOfType(std::size_t index, glm::vec2 from, int type, float radius) const;
    /// The type cells of type `type` that hold the cells a circle around `from` touches: rows
    /// z0..z1, columns x0..x1, the grid starting at entry `base` of the cell starts.
    struct CellBlock {
        std::size_t base;
        int x0, x1, z0, z1;
    };
    CellBlock cellsAround(glm::vec2 from, int type, float radius) const;
    /// Calls visit(entry) for every grid entry within `radius` of `from`.
    template <typename Visit>
    void forEachNear(glm::vec2 from, float radius, Visit&& visit) const;
    int nearestPoint(const std::vector<glm::vec2>& points, glm::vec2 from, float radius) const;

    // The parallel step (CrowdParallelStep.cpp).
    void stepParallel();
    void speculate(int thread, std::atomic<std::size_t>& next);
    bool outcomeHolds(std::size_t index, const Outcome& outcome) const;
    void commit(const Outcome& outcome);
    /// Agent `index` back as the step began (its messages of this step kept).
    void undoSpeculation(std::size_t index);

    CrowdWorld m_world;
    GroundMaps m_maps;
    CrowdFunctions m_code;   // the student's, as the table held them when the crowd was made
    std::vector<CrowdAgent> m_agents;
    std::vector<glm::vec2> m_samples;
    std::vector<glm::vec2> m_crumbs;
    std::vector<glm::vec2> m_trails;      // a ring of trailLength slots, each every agent's position
    int m_trailCount = 0;                 // positions recorded per agent so far
    std::vector<std::string> m_messages;
    std::vector<std::string> m_animations{"stand"};   // the names CrowdAgent::animation indexes
    long long m_step = 0;
    int m_delivered = 0;
    int m_attacks = 0;
    int m_blockedMoves = 0;
    float m_queryReach = 0.0f;   // the farthest an agent's senses and actions look for others, metres
    float m_lookAhead = 0.0f;    // the farthest <blocked ahead>, metres (prefetched)
    bool m_parallelSafe = true;  // no samples or crumbs: what one agent does to the others is a kill or a message
    std::size_t m_parallelFrom = 0;   // living agents from which a step is parallel
    // Per behaviour, the numbers its agents draw as their step begins: its
    // chances first, then its wanders, at most four (StepScratch::kDrawn), each
    // salt mixed as randomUnit() mixes it. A chance decides which way the step
    // goes: drawn early, it is ready when the behaviour asks.
    struct DrawnSalts {
        std::uint32_t mixed[4] = {};
    };
    std::vector<DrawnSalts> m_drawnSalts;

    // The living agents bucketed in square cells, rebuilt after each step:
    // the senses see the others where they stood when the step began, and
    // the step visits the living in this order.
    float m_cellSize = 4.0f;
    int m_cellsX = 1, m_cellsZ = 1;
    float m_lastCell[4] = {};             // m_cellsX - 1, m_cellsZ - 1, twice: cellsAround()'s clamp
    std::vector<int> m_cellStart;         // m_cellsX * m_cellsZ + 1 offsets into m_cellAgents
    std::vector<GridEntry> m_cellAgents;
    // The same per type, for the senses, in cells of 2 x 2 of the step's
    // (kTypeCellShift): an agent in cell (cx, cz) is in type cell (cx >> 1, cz >> 1),
    // so a block of cells is a block of type cells, and a query's answer does
    // not depend on the order of the entries (ties go to the lower index).
    static constexpr int kTypeCellShift = 1;
    int m_typeCellsX = 1, m_typeCellsZ = 1;
    std::vector<int> m_typeCellStart;     // (type * type cells + type cell) + 1 offsets into m_typeCellAgents
    std::vector<GridEntry> m_typeCellAgents;
    std::vector<int> m_cellOf;            // per agent, scratch of rebuildAgentGrid() ...
    std::vector<int> m_typeCellOf;        // ... as is its type cell
    std::vector<int> m_places;                 // per agent, its place in the step's order (m_cellAgents), -1: none
    std::size_t m_place = 0;                   // the place of the agent whose turn it is
    bool m_committing = false;                 // in the parallel step's second pass: the agents after m_place are stepped already
    std::vector<std::uint8_t> m_living;         // per agent, its `alive`, packed for the senses
    // Per agent, what it computed last and may ask again (side by side: one
    // cache line): a heading and its direction() (the heading it ended its
    // last step with, mostly), so that a heading's sine and cosine are
    // computed once; its random numbers' hash of the seed and its index; and the last point its <blocked ahead> asked walkableAt()
    // about with the answer (-1: none yet). walkableAt() answers for a point
    // of a map that never changes, so the same bits get the same answer: an
    // agent that stood still with its heading kept does not ask again.
    struct alignas(32) AgentMemo {   // 32 bytes, aligned: never across two cache lines
        float heading;
        glm::vec2 direction;
        glm::vec2 aheadPoint;
        int aheadWalkable;
        std::uint32_t agentHash;   // randomBase()'s part that is the agent's alone, hashed once
    };
    mutable std::vector<AgentMemo> m_memos;   // a memo only: the const senses fill it
    // The lab's functions as plain function pointers where they were handed
    // over as such (null: called through m_code's StudentFunction).
    bool (*m_walkableAt)(const CollisionMap&, glm::vec2) = nullptr;
    float (*m_heightAt)(const HeightField&, glm::vec2) = nullptr;
    int (*m_arbitrateLayers)(const SubsumptionStack&, const CrowdSenses&) = nullptr;
    int (*m_stepStateMachine)(const StateMachine&, int, const CrowdSenses&, std::vector<const Action*>&) = nullptr;

    // The maps as the prefetch reads them: texel = (xz - min) * scale (not
    // clamped: a prefetch off the map fetches nothing useful and never faults).
    struct GroundMap {
        glm::vec2 min{0.0f};
        glm::vec2 scale{0.0f};
        std::size_t width = 0;   // 0: nothing to prefetch (a map too small for the rows read)
    };
    GroundMap m_prefetchCollision;
    GroundMap m_prefetchHeights;   // shifted half a texel, its last row one up (two rows read)

    std::unique_ptr<StepScratch> m_serialScratch;
    std::vector<StepScratch> m_threadScratch;    // one per thread of the parallel step
    std::vector<Outcome> m_outcomes;             // per place in m_cellAgents
    std::vector<glm::vec2> m_stepKills;          // where this step's victims stood when it began
    std::unique_ptr<StepWorkers> m_workers;
};

} // namespace stoa
