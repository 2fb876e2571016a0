#include <stoa/crowd/CrowdSimulation.hpp>

#include "CrowdMath.hpp"
#include "CrowdStepState.hpp"
#include "HugePages.hpp"
#include "StepWorkers.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <type_traits>

namespace stoa {

using namespace crowdmath;

namespace {

std::string metres(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g m", static_cast<double>(value));
    return text;
}

/// Each cell's count to the end of its run of entries: the running sum in a
/// register (not read back from the array it was just stored to, a wait of
/// several cycles per cell).
void countsToEnds(std::vector<int>& starts) {
    int* count = starts.data();
    const std::size_t cellCount = starts.size() - 1;
    std::size_t c = 0;
    int sum = 0;
#if defined(__SSE2__)
    // Four cells at a time: each lane adds the lanes before it, then the sum so far.
    __m128i before = _mm_setzero_si128();
    for (; c + 4 <= cellCount; c += 4) {
        __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(count + c));
        x = _mm_add_epi32(x, _mm_slli_si128(x, 4));
        x = _mm_add_epi32(x, _mm_slli_si128(x, 8));
        x = _mm_add_epi32(x, before);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(count + c), x);
        before = _mm_shuffle_epi32(x, _MM_SHUFFLE(3, 3, 3, 3));
    }
    sum = _mm_cvtsi128_si32(before);
#endif
    for (; c < cellCount; ++c) count[c] = sum += count[c];
    count[cellCount] = sum;
}

/// `starts` as `size` zeros, by memset (assign() fills an int at a time).
void zeroed(std::vector<int>& starts, std::size_t size) {
    starts.resize(size);
    std::memset(starts.data(), 0, size * sizeof(int));
}

} // namespace

CrowdSimulation::~CrowdSimulation() = default;
CrowdSimulation::CrowdSimulation(CrowdSimulation&&) noexcept = default;
CrowdSimulation& CrowdSimulation::operator=(CrowdSimulation&&) noexcept = default;

CrowdSimulation::CrowdSimulation(const CrowdWorld& world, GroundMaps maps)
    : m_world(world), m_maps(std::move(maps)), m_code(studentCode().crowds),
      m_serialScratch(std::make_unique<StepScratch>()) {
    takeDirectCalls();
    for (const Behaviour& behaviour : m_world.behaviours) {
        const auto collect = [&](const std::vector<Action>& actions, const std::vector<Condition>& conditions) {
            for (const Action& action : actions)
                if (action.kind == Action::Kind::Send && messageIndex(action.target) < 0) m_messages.push_back(action.target);
            for (const Condition& condition : conditions)
                if (condition.kind == Condition::Kind::Message && messageIndex(condition.type) < 0)
                    m_messages.push_back(condition.type);
        };
        for (const MachineState& state : behaviour.machine.states) {
            collect(state.actions, {});
            for (const Transition& transition : state.transitions) collect({}, transition.when);
        }
        for (const Layer& layer : behaviour.stack.layers) collect(layer.actions, layer.when);
    }
    resolveNames();
    if (m_messages.size() > 32) {
        throw InputError(m_world.file.string(), 0,
                         "the world's behaviours use " + std::to_string(m_messages.size()) +
                             " message names; at most 32 are allowed");
    }
    // CrowdAgent keeps its type, base and animation in 16 bits.
    const auto atMost = [&](std::size_t count, const char* what) {
        if (count > 32767) {
            throw InputError(m_world.file.string(), 0,
                             "the world has " + std::to_string(count) + " " + what + "; at most 32,767 are allowed");
        }
    };
    atMost(m_world.types.size(), "agent types");
    atMost(m_world.bases.size(), "bases");
    atMost(m_animations.size(), "animation names");
    float sight = 1.0f;
    for (const AgentType& type : m_world.types) sight = std::max(sight, type.sightRadius);
    // Cells as wide as the longest sight, at most kMaxCells along a side: a
    // wider ground has wider cells (up to 1,024 cells along a side, as many as
    // before, the cells and so the order of the step are the same as before).
    constexpr int kMaxCells = 2048;
    const glm::vec2 size = m_maps.collision.grid.footprintMax - m_maps.collision.grid.footprintMin;
    const float cellsAlong = std::max(size.x, size.y) / sight;
    m_cellSize = cellsAlong > 1024.0f ? std::max(sight, std::max(size.x, size.y) / kMaxCells) : sight;
    m_cellsX = std::max(1, std::min(kMaxCells, static_cast<int>(std::ceil(size.x / m_cellSize))));
    m_cellsZ = std::max(1, std::min(kMaxCells, static_cast<int>(std::ceil(size.y / m_cellSize))));
    m_typeCellsX = ((m_cellsX - 1) >> kTypeCellShift) + 1;
    m_typeCellsZ = ((m_cellsZ - 1) >> kTypeCellShift) + 1;
    m_lastCell[0] = m_lastCell[2] = static_cast<float>(m_cellsX - 1);
    m_lastCell[1] = m_lastCell[3] = static_cast<float>(m_cellsZ - 1);
    measureReaches();
    moveOntoHugePages(m_maps.collision.walkable);
    moveOntoHugePages(m_maps.heights.values);
    const auto prefetched = [](const GroundGrid& grid, float shift, int rowsRead) {
        GroundMap map;
        map.scale = glm::vec2(grid.width, grid.height) / (grid.footprintMax - grid.footprintMin);
        map.min = grid.footprintMin + shift / map.scale;
        map.width = grid.height >= rowsRead ? static_cast<std::size_t>(grid.width) : 0;
        return map;
    };
    m_prefetchCollision = prefetched(m_maps.collision.grid, 0.0f, 1);
    m_prefetchHeights = prefetched(m_maps.heights.grid, 0.5f, 2);
    std::size_t agents = 0;
    for (const SpawnArea& area : m_world.spawns) agents += static_cast<std::size_t>(std::max(0, area.count));
    moveOntoHugePages(m_agents, agents);
    placeSamples();
    placeAgents();
    m_memos.assign(m_agents.size(), AgentMemo{std::numeric_limits<float>::quiet_NaN(), glm::vec2(0.0f), glm::vec2(0.0f), -1, 0});
    for (std::size_t i = 0; i < m_memos.size(); ++i) m_memos[i].agentHash = agentHash(m_world.seed, static_cast<std::uint32_t>(i));
    m_trails.assign(m_agents.size() * trailLength, glm::vec2(0.0f));
    rebuildAgentGrid();
}

void CrowdSimulation::takeDirectCalls() {
    // Through StudentFunction still: it hands over the plain function it holds.
    const auto direct = [](const auto& function, auto& pointer) {
        using Pointer = std::remove_reference_t<decltype(pointer)>;
        const Pointer* held = function.template target<Pointer>();
        pointer = held ? *held : nullptr;
    };
    direct(m_code.walkableAt, m_walkableAt);
    direct(m_code.heightAt, m_heightAt);
    direct(m_code.arbitrateLayers, m_arbitrateLayers);
    direct(m_code.stepStateMachine, m_stepStateMachine);
}

void CrowdSimulation::drawAtStepStart(Behaviour& behaviour) {
    // The chances first (the behaviour's decisions wait on them), then the wanders.
    static_assert(sizeof(DrawnSalts::mixed) / sizeof(std::uint32_t) == StepScratch::kDrawn);
    DrawnSalts salts;
    int count = 0;
    const auto slot = [&](int& index, std::uint32_t salt) {
        if (count == StepScratch::kDrawn) return;   // drawn when asked
        salts.mixed[count] = mixedSalt(salt);
        index = count++;
    };
    const auto chances = [&](std::vector<Condition>& conditions) {
        for (Condition& condition : conditions)
            if (condition.kind == Condition::Kind::Chance) slot(condition.index, static_cast<std::uint32_t>(condition.line) * 2u + 1u);
    };
    const auto wanders = [&](std::vector<Action>& actions) {
        for (Action& action : actions)
            if (action.kind == Action::Kind::Wander) slot(action.index, static_cast<std::uint32_t>(action.line) * 2u);
    };
    for (MachineState& state : behaviour.machine.states)
        for (Transition& transition : state.transitions) chances(transition.when);
    for (Layer& layer : behaviour.stack.layers) chances(layer.when);
    for (MachineState& state : behaviour.machine.states) wanders(state.actions);
    for (Layer& layer : behaviour.stack.layers) wanders(layer.actions);
    m_drawnSalts.push_back(salts);
}

void CrowdSimulation::resolveNames() {
    // Names become indices once, so that a step compares no strings.
    const auto animationIndex = [&](const std::string& name) {
        const auto found = std::find(m_animations.begin(), m_animations.end(), name);
        if (found != m_animations.end()) return static_cast<int>(found - m_animations.begin());
        m_animations.push_back(name);
        return static_cast<int>(m_animations.size() - 1);
    };
    const auto resolveCondition = [&](Condition& condition) {
        if (condition.kind == Condition::Kind::Sees || condition.kind == Condition::Kind::Near)
            condition.index = m_world.findType(condition.type);
        else if (condition.kind == Condition::Kind::Message)
            condition.index = messageIndex(condition.type);
    };
    const auto resolveAction = [&](Action& action) {
        switch (action.kind) {
        case Action::Kind::Seek:
            action.index = action.target == "base"     ? Action::kSeekBase
                           : action.target == "sample" ? Action::kSeekSample
                           : action.target == "crumb"  ? Action::kSeekCrumb
                                                       : m_world.findType(action.target);
            break;
        case Action::Kind::Flee:
        case Action::Kind::Attack: action.index = m_world.findType(action.target); break;
        case Action::Kind::Send: action.index = messageIndex(action.target); break;
        default: break;
        }
    };
    for (Behaviour& behaviour : m_world.behaviours) {
        drawAtStepStart(behaviour);
        for (MachineState& state : behaviour.machine.states) {
            state.animationIndex = animationIndex(state.animation);
            for (Action& action : state.actions) resolveAction(action);
            for (Transition& transition : state.transitions)
                for (Condition& condition : transition.when) resolveCondition(condition);
        }
        for (Layer& layer : behaviour.stack.layers) {
            layer.animationIndex = animationIndex(layer.animation);
            for (Action& action : layer.actions) resolveAction(action);
            for (Condition& condition : layer.when) resolveCondition(condition);
        }
    }
}

std::uint32_t CrowdSimulation::randomBase(std::size_t agent) const {
    return stepHash(agentHash(m_world.seed, static_cast<std::uint32_t>(agent)), m_step);
}

float CrowdSimulation::randomFrom(std::uint32_t base, std::uint32_t salt) { return randomUnit(base, salt); }

float CrowdSimulation::randomFor(std::size_t agent, std::uint32_t salt) const { return randomFrom(randomBase(agent), salt); }

int CrowdSimulation::messageIndex(const std::string& name) const {
    for (std::size_t i = 0; i < m_messages.size(); ++i)
        if (m_messages[i] == name) return static_cast<int>(i);
    return -1;
}

glm::vec2 CrowdSimulation::randomWalkablePoint(glm::vec2 centre, float radius, std::uint32_t salt,
                                               const std::string& what, int line) {
    for (std::uint32_t attempt = 0; attempt < 200; ++attempt) {
        const float angle = 2.0f * kPi * randomFor(salt, attempt * 2u);
        const float distance = radius * std::sqrt(randomFor(salt, attempt * 2u + 1u));
        const glm::vec2 point = centre + distance * direction(angle);
        if (walkable(point)) return point;
    }
    // Whose fault: the map's own texel at the centre says whether the world
    // file put the area on blocked ground or the lab's walkableAt() is wrong.
    char place[96];
    std::snprintf(place, sizeof place, "(%.2f, %.2f)", centre.x, centre.y);
    const CollisionMap& map = m_maps.collision;
    const glm::vec2 texel = (centre - map.grid.footprintMin) / (map.grid.footprintMax - map.grid.footprintMin) *
                            glm::vec2(map.grid.width, map.grid.height);
    const int col = static_cast<int>(std::floor(texel.x)), row = static_cast<int>(std::floor(texel.y));
    const bool mapWalkable = col >= 0 && row >= 0 && col < map.grid.width && row < map.grid.height &&
                             map.walkable[static_cast<std::size_t>(row) * map.grid.width + col] != 0;
    if (mapWalkable) {
        throw InputError(m_world.file.string(), line,
                         "walkableAt() said no to 200 points within " + metres(radius) + " of " + place + " for " + what + ", but the collision map's texel (" +
                             std::to_string(col) + ", " + std::to_string(row) +
                             ") there is white: check walkableAt() (docs/labs/10_crowds.md, \"From a point to a texel\")");
    }
    throw InputError(m_world.file.string(), line,
                     "found no walkable ground for " + what + " within " + metres(radius) + " of " + place + " in 200 tries; move the area onto white in the collision map");
}

void CrowdSimulation::placeSamples() {
    std::uint32_t salt = 0x5A3D0000u;
    for (const SampleArea& area : m_world.samples) {
        for (int i = 0; i < area.count; ++i)
            m_samples.push_back(randomWalkablePoint(area.centre, area.radius, salt++, "a sample", area.line));
    }
}

void CrowdSimulation::placeAgents() {
    std::uint32_t salt = 0xA6E70000u;
    for (std::size_t s = 0; s < m_world.spawns.size(); ++s) {
        const SpawnArea& area = m_world.spawns[s];
        for (int i = 0; i < area.count; ++i) {
            CrowdAgent agent;
            agent.type = area.typeIndex;
            agent.team = m_world.bases.empty() ? 0 : area.team;
            agent.spawn = static_cast<int>(s);
            agent.position = randomWalkablePoint(area.centre, area.radius, salt, "an agent of type '" + area.type + "'",
                                                 area.line);
            agent.heading = 2.0f * kPi * randomFor(salt, 0xFFFFu);
            ++salt;
            agent.y = height(agent.position);
            const Behaviour& behaviour =
                m_world.behaviours[static_cast<std::size_t>(m_world.types[static_cast<std::size_t>(agent.type)].behaviourIndex)];
            if (behaviour.kind == Behaviour::Kind::StateMachine) {
                agent.state = behaviour.machine.initial;
                agent.animation = behaviour.machine.states[static_cast<std::size_t>(agent.state)].animationIndex;
            } else {
                agent.state = -1;
            }
            m_agents.push_back(agent);
        }
    }
}

void CrowdSimulation::measureReaches() {
    // How far the senses and actions of one agent reach others (the parallel
    // step's test of whether a kill could have changed what an agent saw), and
    // whether any of them changes a list all agents share.
    const auto condition = [&](const Condition& c) {
        if (c.kind == Condition::Kind::Near) m_queryReach = std::max(m_queryReach, c.value);
        if (c.kind == Condition::Kind::Blocked) m_lookAhead = std::max(m_lookAhead, c.value);
        if (c.kind == Condition::Kind::SeesSample || c.kind == Condition::Kind::SmellsCrumb) m_parallelSafe = false;
    };
    const auto action = [&](const Action& a) {
        if (a.kind == Action::Kind::Send) m_queryReach = std::max(m_queryReach, a.value);
        if (a.kind == Action::Kind::PickUp || a.kind == Action::Kind::Drop || a.kind == Action::Kind::DropCrumb ||
            a.kind == Action::Kind::PickUpCrumb || a.kind == Action::Kind::FollowCrumbs ||
            (a.kind == Action::Kind::Seek && (a.index == Action::kSeekSample || a.index == Action::kSeekCrumb)))
            m_parallelSafe = false;
    };
    for (const AgentType& type : m_world.types)
        m_queryReach = std::max({m_queryReach, type.sightRadius, type.radius + reach});
    for (const Behaviour& behaviour : m_world.behaviours) {
        for (const MachineState& state : behaviour.machine.states) {
            for (const Action& a : state.actions) action(a);
            for (const Transition& transition : state.transitions)
                for (const Condition& c : transition.when) condition(c);
        }
        for (const Layer& layer : behaviour.stack.layers) {
            for (const Action& a : layer.actions) action(a);
            for (const Condition& c : layer.when) condition(c);
        }
    }
    if (!m_samples.empty() || !m_world.samples.empty()) m_parallelSafe = false;
}

void CrowdSimulation::rebuildAgentGrid() {
    const glm::vec2 origin = m_maps.collision.grid.footprintMin;
    const std::size_t cells = static_cast<std::size_t>(m_cellsX) * m_cellsZ;
    const std::size_t typeCells = static_cast<std::size_t>(m_typeCellsX) * m_typeCellsZ;
    const std::size_t types = std::max<std::size_t>(1, m_world.types.size());
    const std::size_t agentCount = m_agents.size();
    zeroed(m_cellStart, cells + 1);
    zeroed(m_typeCellStart, types * typeCells + 1);
    m_cellOf.resize(agentCount);
    m_typeCellOf.resize(agentCount);
    m_places.resize(agentCount);
    m_living.resize(agentCount);
    // The arrays through local pointers: a store to m_living (bytes, which may
    // alias anything) would otherwise make every member be loaded again.
    CrowdAgent* const agents = m_agents.data();
    std::uint8_t* const living = m_living.data();
    int* const cellOf = m_cellOf.data();
    int* const typeCellOf = m_typeCellOf.data();
    int* const places = m_places.data();
    int* const cellCount = m_cellStart.data();
    int* const typeCellCount = m_typeCellStart.data();
    const float cellSize = m_cellSize;
    const int cellsX = m_cellsX, cellsZ = m_cellsZ, typeCellsX = m_typeCellsX;
    // A counting sort: each cell's count at its own index first ...
    for (std::size_t i = 0; i < agentCount; ++i) {
        CrowdAgent& agent = agents[i];
        // What was sent in the step that ended is heard in the next: passed on
        // here, in the pass that reads every agent anyway, not in one of its own.
        agent.messages = agent.nextMessages;
        agent.nextMessages = 0;
        living[i] = agent.alive ? 1 : 0;
        if (!agent.alive) {
            cellOf[i] = -1;
            places[i] = -1;
            continue;
        }
        const glm::vec2 p = (agent.position - origin) / cellSize;
        const int cx = cellIndex(p.x, cellsX), cz = cellIndex(p.y, cellsZ);
        const int cell = cz * cellsX + cx;
        const int typeCell = agent.type * static_cast<int>(typeCells) + (cz >> kTypeCellShift) * typeCellsX +
                             (cx >> kTypeCellShift);
        cellOf[i] = cell;
        typeCellOf[i] = typeCell;
        ++cellCount[static_cast<std::size_t>(cell)];
        ++typeCellCount[static_cast<std::size_t>(typeCell)];
    }
    // ... then counts to ends ...
    countsToEnds(m_cellStart);
    countsToEnds(m_typeCellStart);
    m_cellAgents.resize(static_cast<std::size_t>(m_cellStart[cells]));
    m_typeCellAgents.resize(m_cellAgents.size());
    // ... and filled from each cell's end back, in falling index order: each
    // end comes down to its cell's start, and within a cell the agents stand
    // by index, the order in which the step visits them.
    GridEntry* const cellAgents = m_cellAgents.data();
    GridEntry* const typeCellAgents = m_typeCellAgents.data();
    for (std::size_t i = agentCount; i-- > 0;) {
        if (cellOf[i] < 0) continue;
        const CrowdAgent& agent = agents[i];
        // Field by field: an entry built whole and then copied waits on its own stores.
        const auto fill = [&](GridEntry& entry) {
            entry.position = agent.position;
            entry.heading = agent.heading;
            entry.agent = static_cast<int>(i);
        };
        const int place = --cellCount[static_cast<std::size_t>(cellOf[i])];
        places[i] = place;
        fill(cellAgents[static_cast<std::size_t>(place)]);
        fill(typeCellAgents[static_cast<std::size_t>(--typeCellCount[static_cast<std::size_t>(typeCellOf[i])])]);
    }
}

void CrowdSimulation::stepTheDead() {
    const float dt = m_world.step;
    m_stepKills.clear();
    // The dead first, in index order (a comeback waits for the next step to
    // act), found by the packed flags: the living's lines are not read here,
    // and no flag when the grid, built from the living, holds every agent.
    if (m_cellAgents.size() == m_agents.size()) return;
    for (std::size_t i = 0; i < m_agents.size(); ++i) {
        if (m_living[i]) continue;
        CrowdAgent& agent = m_agents[i];
        agent.deadFor += dt;
        if (agent.deadFor < respawnSeconds) continue;
        const SpawnArea& area = m_world.spawns[static_cast<std::size_t>(agent.spawn)];
        agent.position = randomWalkablePoint(area.centre, area.radius,
                                             static_cast<std::uint32_t>(i) * 7919u + static_cast<std::uint32_t>(m_step),
                                             "an agent of type '" + area.type + "'", area.line);
        // Back as at the start: standing on its new ground, in its first state.
        agent.alive = true;
        m_living[i] = 1;
        agent.timeInState = 0.0f;
        agent.speed = 0.0f;
        agent.y = height(agent.position);
        agent.animationTime = 0.0f;
        const Behaviour& b = m_world.behaviours[static_cast<std::size_t>(m_world.types[static_cast<std::size_t>(agent.type)].behaviourIndex)];
        if (b.kind == Behaviour::Kind::StateMachine) {
            agent.state = b.machine.initial;
            agent.animation = b.machine.states[static_cast<std::size_t>(agent.state)].animationIndex;
        } else {
            agent.state = -1;
            agent.animation = 0;   // "stand"
        }
    }
}

void CrowdSimulation::step() {
    if (m_workers && m_parallelSafe && m_cellAgents.size() >= m_parallelFrom) {
        stepParallel();
        return;
    }
    stepTheDead();
    // Then the living, cell by cell in the grid's order (built after the last
    // step): agents near each other in space are near each other in the loop,
    // so the map texels and grid cells they read stay in the cache.
    StepScratch& scratch = *m_serialScratch;
    for (std::size_t k = 0; k < m_cellAgents.size(); ++k) {
        // What an agent a few places on will read, on its way already.
        prefetchPlace(k);
        const std::size_t i = static_cast<std::size_t>(m_cellAgents[k].agent);
        if (!m_living[i]) continue;   // attacked earlier in this step
        m_place = k;
        stepAgent(i, m_agents[i], scratch);
    }
    endStep();
}

void CrowdSimulation::endStep() {
    ++m_step;
    if (m_step % trailEvery == 0) {
        // Slot by slot (all agents' positions of one slot side by side): one
        // run of stores, where agent by agent would touch a cache line per agent.
        glm::vec2* const slot = m_trails.data() + static_cast<std::size_t>(m_trailCount % trailLength) * m_agents.size();
        for (std::size_t i = 0; i < m_agents.size(); ++i) slot[i] = m_agents[i].position;
        ++m_trailCount;
    }
    rebuildAgentGrid();
}

void CrowdSimulation::advance(int steps) {
    for (int i = 0; i < steps; ++i) step();
}

std::vector<glm::vec2> CrowdSimulation::trail(std::size_t agent) const {
    std::vector<glm::vec2> points;
    const int count = std::min(m_trailCount, trailLength);
    for (int k = 0; k < count; ++k) {
        const int slot = (m_trailCount - count + k) % trailLength;
        points.push_back(m_trails[static_cast<std::size_t>(slot) * m_agents.size() + agent]);
    }
    return points;
}

CrowdStatistics CrowdSimulation::statistics() const {
    CrowdStatistics s;
    for (const CrowdAgent& agent : m_agents) {
        s.living += agent.alive ? 1 : 0;
        s.carrying += agent.carrying ? 1 : 0;
    }
    s.samplesOnGround = static_cast<int>(m_samples.size());
    s.delivered = m_delivered;
    s.crumbs = static_cast<int>(m_crumbs.size());
    s.attacks = m_attacks;
    s.blockedMoves = m_blockedMoves;
    return s;
}

std::string CrowdSimulation::stateName(std::size_t index) const {
    const CrowdAgent& agent = m_agents[index];
    const Behaviour& behaviour =
        m_world.behaviours[static_cast<std::size_t>(m_world.types[static_cast<std::size_t>(agent.type)].behaviourIndex)];
    if (agent.state < 0) return "";
    if (behaviour.kind == Behaviour::Kind::StateMachine)
        return behaviour.machine.states[static_cast<std::size_t>(agent.state)].name;
    return behaviour.stack.layers[static_cast<std::size_t>(agent.state)].name;
}

} // namespace stoa
