#include <stoa/crowd/CrowdSimulation.hpp>

#include <stoa/core/InputError.hpp>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace stoa {

namespace {

constexpr float kPi = 3.14159265358979f;

std::uint32_t hash32(std::uint32_t x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// Sine, cosine and atan2 from + and * only, so that every machine computes the
// same bits (libm picks its implementation by CPU at run time, and a heading
// that differs in its last bit sends an agent elsewhere a thousand steps later).
// Accurate to about 1e-6, which is all a heading needs.
float wrapAngle(float angle) {
    // floor() by a cast (the headings stay far inside int's range): without
    // SSE4.1 std::floor is a call into libm, and this runs several times per agent.
    const float t = angle * (0.5f / kPi) + 0.5f;
    float turns = static_cast<float>(static_cast<int>(t));
    if (turns > t) turns -= 1.0f;
    return angle - turns * (2.0f * kPi);   // [-pi, pi)
}

float portableSin(float x) {
    x = wrapAngle(x);
    // sin(pi - x) = sin(x) folds [-pi, pi) onto [-pi/2, pi/2].
    if (x > 0.5f * kPi) x = kPi - x;
    else if (x < -0.5f * kPi) x = -kPi - x;
    const float x2 = x * x;
    return x * (1.0f + x2 * (-1.0f / 6.0f + x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 * (1.0f / 362880.0f)))));
}

float portableCos(float x) { return portableSin(x + 0.5f * kPi); }

float portableAtan2(float y, float x) {
    const float ax = std::fabs(x), ay = std::fabs(y);
    if (ax == 0.0f && ay == 0.0f) return 0.0f;
    // atan on [0, 1] from a polynomial in t = min / max, then the octant.
    const float t = std::min(ax, ay) / std::max(ax, ay);
    const float t2 = t * t;
    float a = t * (0.99997726f + t2 * (-0.33262347f + t2 * (0.19354346f + t2 * (-0.11643287f + t2 * (0.05265332f - t2 * 0.01172120f)))));
    if (ay > ax) a = 0.5f * kPi - a;
    if (x < 0.0f) a = kPi - a;
    return y < 0.0f ? -a : a;
}

glm::vec2 direction(float heading) { return {portableSin(heading), portableCos(heading)}; }

/// The grid cell that holds coordinate `cells` (in cell units), clamped to
/// [0, count - 1]: the same as clamp(floor(cells)), without a call into libm
/// (std::floor is one without SSE4.1, and this runs several times per agent).
int cellIndex(float cells, int count) {
    return static_cast<int>(std::clamp(cells, 0.0f, static_cast<float>(count - 1)));
}

std::string metres(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g m", static_cast<double>(value));
    return text;
}

float distanceSquared(glm::vec2 a, glm::vec2 b) {
    const glm::vec2 d = a - b;
    return glm::dot(d, d);
}

} // namespace

/// The conditions of CrowdWorld, answered for one agent at the current step.
class CrowdSimulation::Senses final : public CrowdSenses {
public:
    Senses(const CrowdSimulation& crowd, std::size_t index) : m_crowd(crowd), m_index(index) {}

    bool holds(const Condition& condition) const override { return test(condition) != condition.negated; }

private:
    bool test(const Condition& condition) const {
        const CrowdAgent& agent = m_crowd.m_agents[m_index];
        const AgentType& type = m_crowd.m_world.types[static_cast<std::size_t>(agent.type)];
        switch (condition.kind) {
        case Condition::Kind::Always: return true;
        case Condition::Kind::Sees:
            return m_crowd.nearestAgentOfType(m_index, condition.index, type.sightRadius) >= 0;
        case Condition::Kind::Near:
            return m_crowd.nearestAgentOfType(m_index, condition.index, condition.value) >= 0;
        case Condition::Kind::Carrying: return agent.carrying;
        case Condition::Kind::AtBase: {
            if (m_crowd.m_world.bases.empty()) return false;
            const Base& base = m_crowd.m_world.bases[static_cast<std::size_t>(agent.team)];
            return distanceSquared(agent.position, base.position) <= condition.value * condition.value;
        }
        case Condition::Kind::SeesSample:
            return m_crowd.nearestPoint(m_crowd.m_samples, agent.position, type.sightRadius) >= 0;
        case Condition::Kind::SmellsCrumb:
            return m_crowd.nearestPoint(m_crowd.m_crumbs, agent.position, type.sightRadius) >= 0;
        case Condition::Kind::Blocked:
            return !m_crowd.m_code.walkableAt(m_crowd.m_maps.collision,
                                              agent.position + direction(agent.heading) * condition.value);
        case Condition::Kind::TimeInState: return agent.timeInState >= condition.value;
        case Condition::Kind::Message:
            return condition.index >= 0 && (agent.messages & (1u << condition.index)) != 0;
        case Condition::Kind::Chance:
            return m_crowd.randomFor(m_index, static_cast<std::uint32_t>(condition.line) * 2u + 1u) < condition.value;
        }
        return false;
    }

    const CrowdSimulation& m_crowd;
    std::size_t m_index;
};

CrowdSimulation::CrowdSimulation(const CrowdWorld& world, GroundMaps maps)
    : m_world(world), m_maps(std::move(maps)), m_code(studentCode().crowds) {
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
    float sight = 1.0f;
    for (const AgentType& type : m_world.types) sight = std::max(sight, type.sightRadius);
    m_cellSize = sight;
    const glm::vec2 size = m_maps.collision.grid.footprintMax - m_maps.collision.grid.footprintMin;
    m_cellsX = std::max(1, std::min(1024, static_cast<int>(std::ceil(size.x / m_cellSize))));
    m_cellsZ = std::max(1, std::min(1024, static_cast<int>(std::ceil(size.y / m_cellSize))));
    placeSamples();
    placeAgents();
    m_trails.assign(m_agents.size() * trailLength, glm::vec2(0.0f));
    rebuildAgentGrid();
}

void CrowdSimulation::resolveNames() {
    // Names become indices once, so that a step compares no strings.
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
        for (MachineState& state : behaviour.machine.states) {
            for (Action& action : state.actions) resolveAction(action);
            for (Transition& transition : state.transitions)
                for (Condition& condition : transition.when) resolveCondition(condition);
        }
        for (Layer& layer : behaviour.stack.layers) {
            for (Action& action : layer.actions) resolveAction(action);
            for (Condition& condition : layer.when) resolveCondition(condition);
        }
    }
}

float CrowdSimulation::randomFor(std::size_t agent, std::uint32_t salt) const {
    std::uint32_t x = hash32(m_world.seed * 0x9E3779B9u + static_cast<std::uint32_t>(agent));
    x = hash32(x ^ static_cast<std::uint32_t>(m_step) * 0x85EBCA6Bu);
    x = hash32(x ^ salt * 0xC2B2AE35u);
    return static_cast<float>(x >> 8u) * (1.0f / 16777216.0f);
}

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
        if (m_code.walkableAt(m_maps.collision, point)) return point;
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
            agent.y = m_code.heightAt(m_maps.heights, agent.position);
            const Behaviour& behaviour =
                m_world.behaviours[static_cast<std::size_t>(m_world.types[static_cast<std::size_t>(agent.type)].behaviourIndex)];
            if (behaviour.kind == Behaviour::Kind::StateMachine) {
                agent.state = behaviour.machine.initial;
                agent.animation = behaviour.machine.states[static_cast<std::size_t>(agent.state)].animation;
            } else {
                agent.state = -1;
            }
            m_agents.push_back(agent);
        }
    }
}

void CrowdSimulation::rebuildAgentGrid() {
    const glm::vec2 origin = m_maps.collision.grid.footprintMin;
    const std::size_t cells = static_cast<std::size_t>(m_cellsX) * m_cellsZ;
    m_cellStart.assign(cells + 1, 0);
    m_cellOf.assign(m_agents.size(), -1);
    for (std::size_t i = 0; i < m_agents.size(); ++i) {
        if (!m_agents[i].alive) continue;
        const glm::vec2 p = (m_agents[i].position - origin) / m_cellSize;
        const int cx = cellIndex(p.x, m_cellsX), cz = cellIndex(p.y, m_cellsZ);
        m_cellOf[i] = cz * m_cellsX + cx;
        ++m_cellStart[static_cast<std::size_t>(m_cellOf[i]) + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) m_cellStart[c + 1] += m_cellStart[c];
    m_cellAgents.resize(static_cast<std::size_t>(m_cellStart[cells]));
    std::vector<int> fill(m_cellStart.begin(), m_cellStart.end() - 1);
    for (std::size_t i = 0; i < m_agents.size(); ++i) {
        if (m_cellOf[i] < 0) continue;
        m_cellAgents[static_cast<std::size_t>(fill[static_cast<std::size_t>(m_cellOf[i])]++)] =
            GridEntry{m_agents[i].position, m_agents[i].type, static_cast<int>(i)};
    }
}

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

int CrowdSimulation::nearestAgentOfType(std::size_t index, int type, float radius) const {
    if (type < 0) return -1;
    const glm::vec2 from = m_agents[index].position;
    int best = -1;
    float bestDistance = radius * radius;
    forEachNear(from, radius, [&](const GridEntry& entry) {
        if (entry.type != type || static_cast<std::size_t>(entry.agent) == index) return;
        const float d = distanceSquared(entry.position, from);
        // Ties go to the lower index, whatever order the cells are visited in.
        if (d > bestDistance || (d == bestDistance && best >= 0 && entry.agent > best)) return;
        if (!m_agents[static_cast<std::size_t>(entry.agent)].alive) return;   // attacked this step
        best = entry.agent;
        bestDistance = d;
    });
    return best;
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

void CrowdSimulation::headTowards(CrowdAgent& agent, glm::vec2 target) {
    const glm::vec2 to = target - agent.position;
    if (glm::dot(to, to) > 1e-8f) agent.heading = portableAtan2(to.x, to.y);
}

void CrowdSimulation::runAction(std::size_t index, const Action& action, float speedScale) {
    CrowdAgent& agent = m_agents[index];
    const AgentType& type = m_world.types[static_cast<std::size_t>(agent.type)];
    const float pickReach = type.radius + reach;
    const std::uint32_t salt = static_cast<std::uint32_t>(action.line) * 2u;
    switch (action.kind) {
    case Action::Kind::Wander: {
        const float turn = glm::radians(action.value) * m_world.step;
        agent.heading = wrapAngle(agent.heading + (2.0f * randomFor(index, salt) - 1.0f) * turn);
        agent.speed = type.speed * speedScale;
        break;
    }
    case Action::Kind::Seek: {
        int found = -1;
        glm::vec2 target{0.0f};
        if (action.index == Action::kSeekBase) {
            if (!m_world.bases.empty()) {
                target = m_world.bases[static_cast<std::size_t>(agent.team)].position;
                found = 0;
            }
        } else if (action.index == Action::kSeekSample) {
            found = nearestPoint(m_samples, agent.position, type.sightRadius);
            if (found >= 0) target = m_samples[static_cast<std::size_t>(found)];
        } else if (action.index == Action::kSeekCrumb) {
            found = nearestPoint(m_crumbs, agent.position, type.sightRadius);
            if (found >= 0) target = m_crumbs[static_cast<std::size_t>(found)];
        } else {
            found = nearestAgentOfType(index, action.index, type.sightRadius);
            if (found >= 0) target = m_agents[static_cast<std::size_t>(found)].position;
        }
        if (found >= 0) headTowards(agent, target);
        agent.speed = type.speed * speedScale;
        break;
    }
    case Action::Kind::Flee: {
        const int found = nearestAgentOfType(index, action.index, type.sightRadius);
        if (found >= 0) headTowards(agent, 2.0f * agent.position - m_agents[static_cast<std::size_t>(found)].position);
        agent.speed = type.speed * speedScale;
        break;
    }
    case Action::Kind::FollowCrumbs: {
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
        agent.speed = type.speed * speedScale;
        break;
    }
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
    case Action::Kind::Stop: agent.speed = 0.0f; break;
    case Action::Kind::Send: {
        // Every living agent within the radius, found through the grid, hears it next step.
        const std::uint32_t bit = 1u << action.index;
        forEachNear(agent.position, action.value, [&](const GridEntry& entry) {
            CrowdAgent& hearer = m_agents[static_cast<std::size_t>(entry.agent)];
            if (static_cast<std::size_t>(entry.agent) != index && hearer.alive) hearer.nextMessages |= bit;
        });
        break;
    }
    case Action::Kind::Attack: {
        const int found = nearestAgentOfType(index, action.index, pickReach);
        if (found >= 0) {
            CrowdAgent& victim = m_agents[static_cast<std::size_t>(found)];
            victim.alive = false;
            victim.deadFor = 0.0f;
            if (victim.carrying) m_samples.push_back(victim.position);
            victim.carrying = false;
            ++m_attacks;
        }
        break;
    }
    }
}

void CrowdSimulation::move(std::size_t index) {
    CrowdAgent& agent = m_agents[index];
    const float distance = agent.speed * m_world.step;
    if (distance <= 0.0f) return;
    // Straight on if the collision map lets it; else the smallest turn that does,
    // trying right before left; else stay and turn around.
    static const float turns[] = {0.0f, 0.25f * kPi, -0.25f * kPi, 0.5f * kPi, -0.5f * kPi, 0.75f * kPi, -0.75f * kPi};
    for (const float turn : turns) {
        const float heading = agent.heading + turn;
        const glm::vec2 next = agent.position + direction(heading) * distance;
        if (m_code.walkableAt(m_maps.collision, next)) {
            if (turn != 0.0f) ++m_blockedMoves;
            agent.heading = wrapAngle(heading);
            agent.position = next;
            agent.walkedSinceCrumb += distance;
            return;
        }
    }
    ++m_blockedMoves;
    agent.heading = wrapAngle(agent.heading + kPi);
}

void CrowdSimulation::prefetchMaps(glm::vec2 xz) const {
    const auto texelOf = [&](const GroundGrid& grid) -> std::size_t {
        const glm::vec2 t = (xz - grid.footprintMin) / (grid.footprintMax - grid.footprintMin) *
                            glm::vec2(grid.width, grid.height);
        const int col = std::clamp(static_cast<int>(t.x), 0, grid.width - 1);
        const int row = std::clamp(static_cast<int>(t.y), 0, grid.height - 1);
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.width) + static_cast<std::size_t>(col);
    };
    __builtin_prefetch(m_maps.collision.walkable.data() + texelOf(m_maps.collision.grid));
    const std::size_t height = texelOf(m_maps.heights.grid);
    __builtin_prefetch(m_maps.heights.values.data() + height);
    if (height + static_cast<std::size_t>(m_maps.heights.grid.width) < m_maps.heights.values.size())
        __builtin_prefetch(m_maps.heights.values.data() + height + static_cast<std::size_t>(m_maps.heights.grid.width));
}

void CrowdSimulation::step() {
    const float dt = m_world.step;
    for (CrowdAgent& agent : m_agents) {
        agent.messages = agent.nextMessages;
        agent.nextMessages = 0;
    }
    // The dead first, in index order: a comeback waits for the next step to act.
    for (std::size_t i = 0; i < m_agents.size(); ++i) {
        CrowdAgent& agent = m_agents[i];
        if (!agent.alive) {
            agent.deadFor += dt;
            if (agent.deadFor >= respawnSeconds) {
                const SpawnArea& area = m_world.spawns[static_cast<std::size_t>(agent.spawn)];
                agent.position = randomWalkablePoint(area.centre, area.radius,
                                                     static_cast<std::uint32_t>(i) * 7919u + static_cast<std::uint32_t>(m_step),
                                                     "an agent of type '" + area.type + "'", area.line);
                // Back as at the start: standing on its new ground, in its first state.
                agent.alive = true;
                agent.timeInState = 0.0f;
                agent.speed = 0.0f;
                agent.y = m_code.heightAt(m_maps.heights, agent.position);
                agent.animationTime = 0.0f;
                const Behaviour& b = m_world.behaviours[static_cast<std::size_t>(m_world.types[static_cast<std::size_t>(agent.type)].behaviourIndex)];
                if (b.kind == Behaviour::Kind::StateMachine) {
                    agent.state = b.machine.initial;
                    agent.animation = b.machine.states[static_cast<std::size_t>(agent.state)].animation;
                } else {
                    agent.state = -1;
                    agent.animation = "stand";
                }
            }
        }
    }
    // Then the living, cell by cell in the grid's order (built after the last
    // step): agents near each other in space are near each other in the loop,
    // so the map texels and grid cells they read stay in the cache.
    for (std::size_t k = 0; k < m_cellAgents.size(); ++k) {
        // The texels an agent a few places on will read, on their way already.
        if (k + kPrefetchAhead < m_cellAgents.size()) prefetchMaps(m_cellAgents[k + kPrefetchAhead].position);
        const std::size_t i = static_cast<std::size_t>(m_cellAgents[k].agent);
        CrowdAgent& agent = m_agents[i];
        if (!agent.alive) continue;   // attacked earlier in this step
        const AgentType& type = m_world.types[static_cast<std::size_t>(agent.type)];
        const Behaviour& behaviour = m_world.behaviours[static_cast<std::size_t>(type.behaviourIndex)];
        const Senses senses(*this, i);
        float speedScale = 1.0f;
        static const std::string kStand = "stand";
        const std::string* animation = &kStand;
        int state = -1;
        m_actions.clear();
        if (behaviour.kind == Behaviour::Kind::StateMachine) {
            state = m_code.stepStateMachine(behaviour.machine, agent.state, senses, m_actions);
            if (state < 0 || state >= static_cast<int>(behaviour.machine.states.size())) {
                throw std::out_of_range("stepStateMachine() returned state " + std::to_string(state) + " of behaviour '" +
                                        behaviour.name + "', which has " +
                                        std::to_string(behaviour.machine.states.size()) + " states");
            }
            const MachineState& now = behaviour.machine.states[static_cast<std::size_t>(state)];
            speedScale = now.speedScale;
            animation = &now.animation;
        } else {
            state = m_code.arbitrateLayers(behaviour.stack, senses);
            if (state < -1 || state >= static_cast<int>(behaviour.stack.layers.size())) {
                throw std::out_of_range("arbitrateLayers() returned layer " + std::to_string(state) + " of behaviour '" +
                                        behaviour.name + "', which has " +
                                        std::to_string(behaviour.stack.layers.size()) + " layers");
            }
            if (state >= 0) {
                const Layer& layer = behaviour.stack.layers[static_cast<std::size_t>(state)];
                for (const Action& action : layer.actions) m_actions.push_back(&action);
                speedScale = layer.speedScale;
                animation = &layer.animation;
            }
        }
        if (state != agent.state) {
            agent.timeInState = 0.0f;
            agent.state = state;
            if (*animation != agent.animation) {
                agent.animation = *animation;
                agent.animationTime = 0.0f;
            }
        }
        agent.speed = 0.0f;
        for (const Action* action : m_actions) runAction(i, *action, speedScale);
        const glm::vec2 before = agent.position;
        move(i);
        // The ground only changes under an agent that moved.
        if (agent.position != before) agent.y = m_code.heightAt(m_maps.heights, agent.position);
        agent.timeInState += dt;
        agent.animationTime += dt;
    }
    ++m_step;
    if (m_step % trailEvery == 0) {
        const std::size_t slot = static_cast<std::size_t>(m_trailCount % trailLength);
        for (std::size_t i = 0; i < m_agents.size(); ++i) m_trails[i * trailLength + slot] = m_agents[i].position;
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
        points.push_back(m_trails[agent * trailLength + static_cast<std::size_t>(slot)]);
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
