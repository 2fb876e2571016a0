// One living agent's step: its senses, its behaviour (the lab's), its actions
// and its move. The serial step runs it on the agent itself; the parallel
// step's first pass on a copy, recording what it does to the others
// (CrowdParallelStep.cpp).

#include <stoa/crowd/CrowdSimulation.hpp>

#include "CrowdMath.hpp"
#include "CrowdStepState.hpp"

#include <glm/trigonometric.hpp>

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace stoa {

using namespace crowdmath;

namespace {

void headTowards(CrowdAgent& agent, glm::vec2 target) {
    const glm::vec2 to = target - agent.position;
    if (glm::dot(to, to) > 1e-8f) agent.heading = portableAtan2(to.x, to.y);
}

/// Whether an action reads or changes other agents (a kill before it changes what it finds).
bool readsOthers(Action::Kind kind) {
    return kind == Action::Kind::Seek || kind == Action::Kind::Flee || kind == Action::Kind::Send ||
           kind == Action::Kind::Attack;
}

bool sameBits(float a, float b) {
    std::uint32_t x = 0, y = 0;
    std::memcpy(&x, &a, sizeof x);
    std::memcpy(&y, &b, sizeof y);
    return x == y;
}

} // namespace

/// The conditions of CrowdWorld, answered for one agent at the current step.
class CrowdSimulation::Senses final : public CrowdSenses {
public:
    Senses(const CrowdSimulation& crowd, std::size_t index, const CrowdAgent& agent, float sight, StepScratch& scratch)
        : m_crowd(crowd), m_index(index), m_agent(agent), m_sight(sight), m_scratch(scratch) {}

    bool holds(const Condition& condition) const override { return test(condition) != condition.negated; }

private:
    bool test(const Condition& condition) const {
        const CrowdAgent& agent = m_agent;
        switch (condition.kind) {
        case Condition::Kind::Always: return true;
        case Condition::Kind::Sees:
            return m_crowd.anyAgentOfType(m_index, agent.position, condition.index, m_sight);
        case Condition::Kind::Near:
            return m_crowd.anyAgentOfType(m_index, agent.position, condition.index, condition.value);
        case Condition::Kind::Carrying: return agent.carrying;
        case Condition::Kind::AtBase: {
            if (m_crowd.m_world.bases.empty()) return false;
            const Base& base = m_crowd.m_world.bases[static_cast<std::size_t>(agent.team)];
            return distanceSquared(agent.position, base.position) <= condition.value * condition.value;
        }
        case Condition::Kind::SeesSample:
            return m_crowd.nearestPoint(m_crowd.m_samples, agent.position, m_sight) >= 0;
        case Condition::Kind::SmellsCrumb:
            return m_crowd.nearestPoint(m_crowd.m_crumbs, agent.position, m_sight) >= 0;
        case Condition::Kind::Blocked:
            return !m_crowd.walkableAhead(m_index, agent.position + headingDirection(m_scratch, agent.heading) * condition.value);
        case Condition::Kind::TimeInState: return agent.timeInState >= condition.value;
        case Condition::Kind::Message:
            return condition.index >= 0 && (agent.messages & (1u << condition.index)) != 0;
        case Condition::Kind::Chance:
            return m_crowd.randomOf(m_scratch, condition.index, static_cast<std::uint32_t>(condition.line) * 2u + 1u) < condition.value;
        }
        return false;
    }

    const CrowdSimulation& m_crowd;
    std::size_t m_index;
    const CrowdAgent& m_agent;   // m_crowd's agent m_index, or its copy in the parallel pass
    float m_sight;               // its type's sight radius
    StepScratch& m_scratch;
};

template <typename Visit>
void CrowdSimulation::forEachNear(glm::vec2 from, float radius, Visit&& visit) const {
    const glm::vec2 origin = m_maps.collision.grid.footprintMin;
    const glm::vec2 low = (from - radius - origin) / m_cellSize;
    const glm::vec2 high = (from + radius - origin) / m_cellSize;
    const int x0 = cellIndex(low.x, m_cellsX), x1 = cellIndex(high.x, m_cellsX);
    const int z0 = cellIndex(low.y, m_cellsZ), z1 = cellIndex(high.y, m_cellsZ);
    const float r2 = radius * radius;
    for (int cz = z0; cz <= z1; ++cz) {
        for (int cx = x0; cx <= x1; ++cx) {
            const std::size_t cell = static_cast<std::size_t>(cz) * m_cellsX + cx;
            for (int k = m_cellStart[cell]; k < m_cellStart[cell + 1]; ++k) {
                const GridEntry& entry = m_cellAgents[static_cast<std::size_t>(k)];
                if (distanceSquared(entry.position, from) <= r2) visit(entry);
            }
        }
    }
}

CrowdSimulation::CellBlock CrowdSimulation::cellsAround(glm::vec2 from, int type, float radius) const {
    const glm::vec2 origin = m_maps.collision.grid.footprintMin;
    const std::size_t base = static_cast<std::size_t>(type) * static_cast<std::size_t>(m_typeCellsX) * m_typeCellsZ;
    // The block of the step's cells, then the type cells that hold them.
    constexpr int s = kTypeCellShift;
#if defined(__SSE2__)
    // The block's four edges side by side, each lane the same operations in
    // the same order as below (x + -r is x - r exactly; max then min is the
    // clamp for any number that is not NaN), so the same cells.
    const __m128 edges = _mm_add_ps(_mm_setr_ps(from.x, from.y, from.x, from.y), _mm_setr_ps(-radius, -radius, radius, radius));
    __m128 cells = _mm_div_ps(_mm_sub_ps(edges, _mm_setr_ps(origin.x, origin.y, origin.x, origin.y)), _mm_set1_ps(m_cellSize));
    cells = _mm_min_ps(_mm_max_ps(cells, _mm_setzero_ps()), _mm_loadu_ps(m_lastCell));
    alignas(16) int index[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(index), _mm_cvttps_epi32(cells));
    return {base, index[0] >> s, index[2] >> s, index[1] >> s, index[3] >> s};
#else
    const glm::vec2 low = (from - radius - origin) / m_cellSize;
    const glm::vec2 high = (from + radius - origin) / m_cellSize;
    return {base, cellIndex(low.x, m_cellsX) >> s, cellIndex(high.x, m_cellsX) >> s, cellIndex(low.y, m_cellsZ) >> s,
            cellIndex(high.y, m_cellsZ) >> s};
#endif
}

int CrowdSimulation::nearestAgentOfType(std::size_t index, glm::vec2 from, int type, float radius) const {
    if (type < 0) return -1;
    int best = -1;
    float bestDistance = radius * radius;
    const CellBlock cells = cellsAround(from, type, radius);
    for (int cz = cells.z0; cz <= cells.z1; ++cz) {
        const std::size_t row = cells.base + static_cast<std::size_t>(cz) * m_typeCellsX;
        // The cells of one row of the type's grid lie side by side: one run of entries.
        const int end = m_typeCellStart[row + static_cast<std::size_t>(cells.x1) + 1];
        for (int k = m_typeCellStart[row + static_cast<std::size_t>(cells.x0)]; k < end; ++k) {
            const GridEntry& entry = m_typeCellAgents[static_cast<std::size_t>(k)];
            const float d = distanceSquared(entry.position, from);
            // Ties go to the lower index, whatever order the cells are visited in.
            if (d > bestDistance || (d == bestDistance && best >= 0 && entry.agent > best)) continue;
            if (static_cast<std::size_t>(entry.agent) == index) continue;
            if (!m_living[static_cast<std::size_t>(entry.agent)]) continue;   // attacked this step
            best = entry.agent;
            bestDistance = d;
        }
    }
    return best;
}

bool CrowdSimulation::anyAgentOfType(std::size_t index, glm::vec2 from, int type, float radius) const {
    if (type < 0) return false;
    const float r2 = radius * radius;
    const CellBlock cells = cellsAround(from, type, radius);
    const auto anyInRow = [&](int cz) {
        const std::size_t row = cells.base + static_cast<std::size_t>(cz) * m_typeCellsX;
        const int end = m_typeCellStart[row + static_cast<std::size_t>(cells.x1) + 1];
        for (int k = m_typeCellStart[row + static_cast<std::size_t>(cells.x0)]; k < end; ++k) {
            const GridEntry& entry = m_typeCellAgents[static_cast<std::size_t>(k)];
            if (distanceSquared(entry.position, from) <= r2 && static_cast<std::size_t>(entry.agent) != index &&
                m_living[static_cast<std::size_t>(entry.agent)])
                return true;
        }
        return false;
    };
    // A block of one row or two (always so for a radius up to the longest
    // sight: a type cell is two sights wide) is read as its first row and its
    // last, one row read twice where there is one: a loop over one or two rows
    // mispredicts its end about every other query.
    if (cells.z1 - cells.z0 <= 1) return anyInRow(cells.z0) || anyInRow(cells.z1);
    for (int cz = cells.z0; cz <= cells.z1; ++cz)
        if (anyInRow(cz)) return true;
    return false;
}

int CrowdSimulation::nearestPoint(const std::vector<glm::vec2>& points, glm::vec2 from, float radius) const {
    int best = -1;
    float bestDistance = radius * radius;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const float d = distanceSquared(points[i], from);
        if (d <= bestDistance && (best < 0 || d < bestDistance)) {
            best = static_cast<int>(i);
            bestDistance = d;
        }
    }
    return best;
}

float CrowdSimulation::randomOf(const StepScratch& scratch, int drawn, std::uint32_t salt) {
    return drawn >= 0 ? scratch.drawn[drawn] : randomUnit(scratch.randomBase, salt);
}

glm::vec2 CrowdSimulation::targetPosition(int found, StepScratch& scratch) const {
    // Where the agent whose turn it is sees it: moved if its turn has come
    // (in the parallel step, agents after it have moved ahead of theirs).
    const auto other = static_cast<std::size_t>(found);
    if (!scratch.outcome)
        return m_places[other] < static_cast<int>(m_place) ? m_agents[other].position : startPosition(other);
    // It may have moved by the agent's turn: the turn checks that it has not.
    const glm::vec2 position = startPosition(other);
    Outcome& outcome = *scratch.outcome;
    if (outcome.targetCount == Outcome::kMaxReads) {
        outcome.redo = true;
    } else {
        outcome.targets[outcome.targetCount] = found;
        outcome.targetPositions[outcome.targetCount++] = position;
    }
    return position;
}

glm::vec2 CrowdSimulation::headingDirection(StepScratch& scratch, float heading) {
    // direction() of the same bits gives the same bits.
    for (int m = 0; m < scratch.memoCount; ++m)
        if (sameBits(scratch.memoHeadings[m], heading)) return scratch.memoDirections[m];
    const int slot = scratch.memoNext;
    scratch.memoNext = (scratch.memoNext + 1) % StepScratch::kMemo;
    scratch.memoCount = std::max(scratch.memoCount, slot + 1);
    scratch.memoHeadings[slot] = heading;
    scratch.memoDirections[slot] = direction(heading);
    return scratch.memoDirections[slot];
}

bool CrowdSimulation::walkable(glm::vec2 xz) const {
    return m_walkableAt ? m_walkableAt(m_maps.collision, xz) : m_code.walkableAt(m_maps.collision, xz);
}

bool CrowdSimulation::walkableAhead(std::size_t index, glm::vec2 point) const {
    AgentMemo& memo = m_memos[index];
    if (memo.aheadWalkable >= 0 && sameBits(memo.aheadPoint.x, point.x) && sameBits(memo.aheadPoint.y, point.y))
        return memo.aheadWalkable != 0;
    const bool answer = walkable(point);
    memo.aheadPoint = point;
    memo.aheadWalkable = answer ? 1 : 0;
    return answer;
}

float CrowdSimulation::height(glm::vec2 xz) const {
    return m_heightAt ? m_heightAt(m_maps.heights, xz) : m_code.heightAt(m_maps.heights, xz);
}

void CrowdSimulation::kill(std::size_t victimIndex) {
    // One whose turn is still to come has stepped ahead of it: it never does.
    if (m_committing && m_places[victimIndex] > static_cast<int>(m_place)) undoSpeculation(victimIndex);
    CrowdAgent& victim = m_agents[victimIndex];
    victim.alive = false;
    m_living[victimIndex] = 0;
    victim.deadFor = 0.0f;
    if (victim.carrying) m_samples.push_back(victim.position);
    victim.carrying = false;
    ++m_attacks;
    m_stepKills.push_back(startPosition(victimIndex));
}

bool CrowdSimulation::seekTarget(std::size_t index, const CrowdAgent& agent, const Action& action,
                                 StepScratch& scratch, glm::vec2& target) const {
    const AgentType& type = m_world.types[static_cast<std::size_t>(agent.type)];
    int found = -1;
    if (action.index == Action::kSeekBase) {
        if (m_world.bases.empty()) return false;
        target = m_world.bases[static_cast<std::size_t>(agent.team)].position;
        return true;
    }
    if (action.index == Action::kSeekSample) {
        found = nearestPoint(m_samples, agent.position, type.sightRadius);
        if (found >= 0) target = m_samples[static_cast<std::size_t>(found)];
    } else if (action.index == Action::kSeekCrumb) {
        found = nearestPoint(m_crumbs, agent.position, type.sightRadius);
        if (found >= 0) target = m_crumbs[static_cast<std::size_t>(found)];
    } else {
        found = nearestAgentOfType(index, agent.position, action.index, type.sightRadius);
        if (found >= 0) target = targetPosition(found, scratch);
    }
    return found >= 0;
}

void CrowdSimulation::followCrumbs(CrowdAgent& agent) const {
    const AgentType& type = m_world.types[static_cast<std::size_t>(agent.type)];
    // The crumb within sight farthest from the base leads away from it, towards the samples.
    const glm::vec2 base = m_world.bases.empty() ? agent.position : m_world.bases[static_cast<std::size_t>(agent.team)].position;
    int best = -1;
    float bestFromBase = -1.0f;
    const float sight2 = type.sightRadius * type.sightRadius;
    for (std::size_t i = 0; i < m_crumbs.size(); ++i) {
        if (distanceSquared(m_crumbs[i], agent.position) > sight2) continue;
        const float fromBase = distanceSquared(m_crumbs[i], base);
        if (fromBase > bestFromBase) {
            best = static_cast<int>(i);
            bestFromBase = fromBase;
        }
    }
    if (best >= 0) headTowards(agent, m_crumbs[static_cast<std::size_t>(best)]);
}

void CrowdSimulation::runSharedListAction(CrowdAgent& agent, const Action& action) {
    const float pickReach = m_world.types[static_cast<std::size_t>(agent.type)].radius + reach;
    switch (action.kind) {
    case Action::Kind::PickUp: {
        if (agent.carrying) break;
        const int found = nearestPoint(m_samples, agent.position, pickReach);
        if (found >= 0) {
            m_samples.erase(m_samples.begin() + found);
            agent.carrying = true;
        }
        break;
    }
    case Action::Kind::Drop: {
        if (!agent.carrying) break;
        agent.carrying = false;
        const bool atBase = !m_world.bases.empty() &&
                            distanceSquared(agent.position, m_world.bases[static_cast<std::size_t>(agent.team)].position) <=
                                m_world.bases[static_cast<std::size_t>(agent.team)].radius *
                                    m_world.bases[static_cast<std::size_t>(agent.team)].radius;
        if (atBase) ++m_delivered;
        else m_samples.push_back(agent.position);
        break;
    }
    case Action::Kind::DropCrumb:
        if (agent.walkedSinceCrumb >= crumbSpacing && m_crumbs.size() < static_cast<std::size_t>(maxCrumbs)) {
            m_crumbs.push_back(agent.position);
            agent.walkedSinceCrumb = 0.0f;
        }
        break;
    case Action::Kind::PickUpCrumb: {
        const int found = nearestPoint(m_crumbs, agent.position, pickReach);
        if (found >= 0) m_crumbs.erase(m_crumbs.begin() + found);
        break;
    }
    default: break;
    }
}

inline void CrowdSimulation::runAction(std::size_t index, CrowdAgent& agent, const Action& action, float speedScale,
                                       StepScratch& scratch) {
    // Neither reads nor changes the others: no test of a kill before them in the parallel pass.
    if (action.kind == Action::Kind::Stop) {
        agent.speed = 0.0f;
    } else if (action.kind == Action::Kind::Wander) {
        const float turn = glm::radians(action.value) * m_world.step;
        const float random = randomOf(scratch, action.index, static_cast<std::uint32_t>(action.line) * 2u);
        agent.heading = wrapAngle(agent.heading + (2.0f * random - 1.0f) * turn);
        agent.speed = m_world.types[static_cast<std::size_t>(agent.type)].speed * speedScale;
    } else {
        runOtherAction(index, agent, action, speedScale, scratch);
    }
}

void CrowdSimulation::runOtherAction(std::size_t index, CrowdAgent& agent, const Action& action, float speedScale,
                                     StepScratch& scratch) {
    if (scratch.outcome && scratch.outcome->victim >= 0 && readsOthers(action.kind)) {
        // After a kill the others are not as the parallel pass sees them: step it in its turn.
        scratch.outcome->redo = true;
        return;
    }
    const AgentType& type = m_world.types[static_cast<std::size_t>(agent.type)];
    const float pickReach = type.radius + reach;
    switch (action.kind) {
    case Action::Kind::Seek: {
        glm::vec2 target{0.0f};
        if (seekTarget(index, agent, action, scratch, target)) headTowards(agent, target);
        agent.speed = type.speed * speedScale;
        break;
    }
    case Action::Kind::Flee: {
        const int found = nearestAgentOfType(index, agent.position, action.index, type.sightRadius);
        if (found >= 0) headTowards(agent, 2.0f * agent.position - targetPosition(found, scratch));
        agent.speed = type.speed * speedScale;
        break;
    }
    case Action::Kind::FollowCrumbs:
        followCrumbs(agent);
        agent.speed = type.speed * speedScale;
        break;
    case Action::Kind::PickUp:
    case Action::Kind::Drop:
    case Action::Kind::DropCrumb:
    case Action::Kind::PickUpCrumb: runSharedListAction(agent, action); break;
    case Action::Kind::Stop:
    case Action::Kind::Wander: break;   // runAction()'s
    case Action::Kind::Send: {
        // Every living agent within the radius, found through the grid, hears it next step.
        const std::uint32_t bit = 1u << action.index;
        forEachNear(agent.position, action.value, [&](const GridEntry& entry) {
            CrowdAgent& hearer = m_agents[static_cast<std::size_t>(entry.agent)];
            if (static_cast<std::size_t>(entry.agent) == index || !m_living[static_cast<std::size_t>(entry.agent)]) return;
            if (scratch.outcome) scratch.heard.emplace_back(entry.agent, bit);
            else hearer.nextMessages |= bit;
        });
        break;
    }
    case Action::Kind::Attack: {
        const int found = nearestAgentOfType(index, agent.position, action.index, pickReach);
        if (found < 0) break;
        if (scratch.outcome) scratch.outcome->victim = found;
        else kill(static_cast<std::size_t>(found));
        break;
    }
    }
}

void CrowdSimulation::move(CrowdAgent& agent, StepScratch& scratch) {
    const float distance = agent.speed * m_world.step;
    if (distance <= 0.0f) return;
    int& blocked = scratch.outcome ? scratch.outcome->blocked : m_blockedMoves;
    // Straight on if the collision map lets it; else the smallest turn that does,
    // trying right before left; else stay and turn around.
    static const float turns[] = {0.0f, 0.25f * kPi, -0.25f * kPi, 0.5f * kPi, -0.5f * kPi, 0.75f * kPi, -0.75f * kPi};
    for (const float turn : turns) {
        const float heading = agent.heading + turn;
        const glm::vec2 next = agent.position + headingDirection(scratch, heading) * distance;
        if (walkable(next)) {
            if (turn != 0.0f) ++blocked;
            agent.heading = wrapAngle(heading);
            agent.position = next;
            agent.walkedSinceCrumb += distance;
            return;
        }
    }
    ++blocked;
    agent.heading = wrapAngle(agent.heading + kPi);
}

void CrowdSimulation::prefetchPlace(std::size_t place) const {
    // The agents' own states lie in index order, not in the step's: each is
    // fetched twice as far ahead as the map texels it will read.
    const std::size_t count = m_cellAgents.size();
    const GridEntry* entries = m_cellAgents.data();
    if (place + 2 * kPrefetchAhead < count) {
        const auto far = static_cast<std::size_t>(entries[place + 2 * kPrefetchAhead].agent);
        const char* state = reinterpret_cast<const char*>(m_agents.data() + far);
        __builtin_prefetch(state);   // one cache line (CrowdAgent is 64 bytes, aligned)
        // And its memo, which the prefetch below reads when it comes kPrefetchAhead places on.
        __builtin_prefetch(m_memos.data() + far);
    }
    if (place + kPrefetchAhead >= count) return;
    // The texel under it and the two rows of heights around it (heightAt() is
    // bilinear between texel centres); the texel under it is the one the move reads.
    // A prefetch never faults, so an address off the map needs no clamp: the
    // address is computed as a number, and a point off the map fetches nothing useful.
    const GridEntry& entry = entries[place + kPrefetchAhead];
    const auto texelAddress = [](const GroundMap& map, std::uintptr_t base, std::size_t bytes, glm::vec2 xz) {
        const glm::vec2 t = (xz - map.min) * map.scale;
        const auto col = static_cast<std::intptr_t>(static_cast<int>(t.x));
        const auto row = static_cast<std::intptr_t>(static_cast<int>(t.y));
        return reinterpret_cast<const void*>(base + static_cast<std::uintptr_t>((row * static_cast<std::intptr_t>(map.width) + col) *
                                                                                 static_cast<std::intptr_t>(bytes)));
    };
    const auto walkable = reinterpret_cast<std::uintptr_t>(m_maps.collision.walkable.data());
    __builtin_prefetch(texelAddress(m_prefetchCollision, walkable, 1, entry.position));
    // And the texel `blocked ahead` reads, where the heading's direction is known.
    const AgentMemo& memo = m_memos[static_cast<std::size_t>(entry.agent)];
    if (m_lookAhead > 0.0f && sameBits(memo.heading, entry.heading))
        __builtin_prefetch(texelAddress(m_prefetchCollision, walkable, 1, entry.position + memo.direction * m_lookAhead));
    if (m_prefetchHeights.width == 0) return;
    const auto heights = reinterpret_cast<std::uintptr_t>(m_maps.heights.values.data());
    const char* texel = static_cast<const char*>(texelAddress(m_prefetchHeights, heights, sizeof(float), entry.position));
    __builtin_prefetch(texel);
    __builtin_prefetch(texel + m_prefetchHeights.width * sizeof(float));
}

void CrowdSimulation::stepAgent(std::size_t index, CrowdAgent& agent, StepScratch& scratch) {
    const float dt = m_world.step;
    const AgentType& type = m_world.types[static_cast<std::size_t>(agent.type)];
    const Behaviour& behaviour = m_world.behaviours[static_cast<std::size_t>(type.behaviourIndex)];
    // Nearly every agent draws a number each step (a chance, a wander): its
    // behaviour's first four at once, not on the first ask.
    scratch.randomBase = stepHash(m_memos[index].agentHash, m_step);
    randomUnits(scratch.randomBase, m_drawnSalts[static_cast<std::size_t>(type.behaviourIndex)].mixed, scratch.drawn);
    scratch.memoCount = 1;
    scratch.memoNext = 1;
    scratch.memoHeadings[0] = m_memos[index].heading;
    scratch.memoDirections[0] = m_memos[index].direction;
    const Senses senses(*this, index, agent, type.sightRadius, scratch);
    float speedScale = 1.0f;
    int animation = 0;   // "stand", where no layer fires
    int state = -1;
    std::vector<const Action*>& actions = scratch.actions;   // what stepStateMachine() chose ...
    const std::vector<Action>* layerActions = nullptr;        // ... or the layer that fired
    if (behaviour.kind == Behaviour::Kind::StateMachine) {
        actions.clear();
        state = m_stepStateMachine ? m_stepStateMachine(behaviour.machine, agent.state, senses, actions)
                                   : m_code.stepStateMachine(behaviour.machine, agent.state, senses, actions);
        if (state < 0 || state >= static_cast<int>(behaviour.machine.states.size())) {
            throw std::out_of_range("stepStateMachine() returned state " + std::to_string(state) + " of behaviour '" +
                                    behaviour.name + "', which has " +
                                    std::to_string(behaviour.machine.states.size()) + " states");
        }
        const MachineState& now = behaviour.machine.states[static_cast<std::size_t>(state)];
        speedScale = now.speedScale;
        animation = now.animationIndex;
    } else {
        state = m_arbitrateLayers ? m_arbitrateLayers(behaviour.stack, senses) : m_code.arbitrateLayers(behaviour.stack, senses);
        if (state < -1 || state >= static_cast<int>(behaviour.stack.layers.size())) {
            throw std::out_of_range("arbitrateLayers() returned layer " + std::to_string(state) + " of behaviour '" +
                                    behaviour.name + "', which has " +
                                    std::to_string(behaviour.stack.layers.size()) + " layers");
        }
        if (state >= 0) {
            const Layer& layer = behaviour.stack.layers[static_cast<std::size_t>(state)];
            layerActions = &layer.actions;
            speedScale = layer.speedScale;
            animation = layer.animationIndex;
        }
    }
    if (state != agent.state) {
        agent.timeInState = 0.0f;
        agent.state = state;
        if (animation != agent.animation) {
            agent.animation = animation;
            agent.animationTime = 0.0f;
        }
    }
    agent.speed = 0.0f;
    if (layerActions) {
        for (const Action& action : *layerActions) runAction(index, agent, action, speedScale, scratch);
    } else if (behaviour.kind == Behaviour::Kind::StateMachine) {
        for (const Action* action : actions) runAction(index, agent, *action, speedScale, scratch);
    }
    // Only an agent with somewhere to go moves (most of a grazing herd stands),
    // and the ground only changes under an agent that moved.
    if (agent.speed * m_world.step > 0.0f) {
        const glm::vec2 before = agent.position;
        move(agent, scratch);
        if (agent.position != before) agent.y = height(agent.position);
    }
    agent.timeInState += dt;
    agent.animationTime += dt;
    // The direction of the heading it ends with, for its next step.
    for (int m = 0; m < scratch.memoCount; ++m) {
        if (sameBits(scratch.memoHeadings[m], agent.heading)) {
            m_memos[index].heading = agent.heading;
            m_memos[index].direction = scratch.memoDirections[m];
            break;   // any entry of the same bits holds the same direction
        }
    }
}

} // namespace stoa
