// Lab 10's six functions (labs/10_crowds/student/lab10.hpp) against independent
// references written here, in double where there is arithmetic:
//   - stepStateMachine and arbitrateLayers, asked through a fake CrowdSenses
//     that answers every condition from a table (keyed by the condition's
//     `type`: the tests name their conditions "a", "b", ...): the first
//     transition whose conditions all hold fires, an empty list fires, none
//     firing keeps the state, the actions are the new state's in their order,
//     `actions` is cleared first, `negated` is left to the senses; the first
//     layer from the top fires, a layer without conditions always does, -1 when
//     none does; then both against a reference (std::find_if over std::all_of)
//     on 2,000 random machines and stacks with random tables;
//   - walkableAt against an interval test per texel in double: at every texel
//     corner and centre and just inside every corner, on a non-square map over a
//     non-square footprint whose cells are powers of two (so the corners are
//     exact in float too), row 0 along z = footprintMin.y, column 0 along
//     x = footprintMin.x, false outside and on the far edges; random points on
//     a 64 x 48 map over [-15, 15]^2 (those within 1e-4 texel of an edge left out);
//   - heightAt against the bilinear blend written as a sum of tent weights
//     over every texel (clamped texel coordinates): exact at the texel centres,
//     the mean of four samples midway between their centres, random points in
//     and around the footprint, the edge values outside it, heightMin and
//     heightMax for values 0 and 1, a 1 x 1 field;
//   - md2FramesAt against fmod in double: frame k at k / fps, the last frame
//     blending into the animation's own first, seconds past a thousand loops, a
//     one-frame animation, indices offset by animation.first, t in [0, 1) on a
//     sweep and just below loop boundaries, and 5,000 random cases compared as
//     a phase on the loop (so that k - 1 with t near 1 matches k with t near 0);
//   - blendMd2Frames: t = 0 and 1 give the frames, positions the mix in double,
//     normals of unit length along the normalized mix, outputs resized from
//     longer and shorter vectors;
//   - writeExampleGroundMaps (GroundMapMaker.hpp, in the stoa library, hence
//     here) writes exactly the committed assets/crowds maps.
// The planted mistakes of solutions/10_crowds/mistakes/ (all in C++) each fail
// cases here (checked by applying each one's find/replace to a copy of the solution):
//   any_condition_fires        stepStateMachine "all its conditions", "keeps the state", random
//                              machines; arbitrateLayers "all conditions must hold", random stacks
//   transitions_after_actions  stepStateMachine "no conditions", "the new state's", random machines
//   layers_reversed            arbitrateLayers "first from the top", "all conditions", random stacks
//   map_v_flipped              every walkableAt case but "outside the footprint"
//   heights_nearest            heightAt "midway", "in and around", "values 0 and 1"
//   no_wrap_to_first_frame     every md2FramesAt case but "one-frame" and "offset"
// and the two the lab dropped: heights_without_half_texel (five heightAt cases),
// normals_not_renormalized (blendMd2Frames "unit length").

#include "catch.hpp"
#include "TempFolder.hpp"
#include "TestRandom.hpp"
#include "lab10.hpp"

#include <stoa/core/Paths.hpp>
#include <stoa/crowd/CrowdLab.hpp>
#include <stoa/scene/GroundMapMaker.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace stoa;

namespace {

using Table = std::map<std::string, bool>;

/// Answers each condition from a table by its `type`; a condition the table
/// does not know is a mistake in the test. `negated` is not applied: the
/// simulation's senses apply it before the student's code sees the answer.
class TableSenses final : public CrowdSenses {
public:
    explicit TableSenses(Table table) : m_table(std::move(table)) {}
    bool holds(const Condition& condition) const override {
        const auto found = m_table.find(condition.type);
        if (found == m_table.end()) throw std::logic_error("TableSenses: no answer for '" + condition.type + "'");
        return found->second;
    }

private:
    Table m_table;
};

Condition condition(const std::string& name, bool negated = false) {
    Condition c;
    c.kind = Condition::Kind::Message;
    c.type = name;
    c.negated = negated;
    return c;
}

std::vector<Condition> conditions(const std::vector<std::string>& names) {
    std::vector<Condition> list;
    for (const std::string& name : names) list.push_back(condition(name));
    return list;
}

Transition transition(const std::vector<std::string>& when, int target) {
    Transition t;
    t.when = conditions(when);
    t.target = target;
    return t;
}

/// A state whose actions are told apart by their lines (firstLine, firstLine + 1, ...).
MachineState machineState(std::vector<Transition> transitions, int actionCount, int firstLine) {
    MachineState state;
    state.name = "s" + std::to_string(firstLine);
    state.transitions = std::move(transitions);
    for (int i = 0; i < actionCount; ++i) {
        Action action;
        action.kind = Action::Kind::Wander;
        action.line = firstLine + i;
        state.actions.push_back(action);
    }
    return state;
}

std::vector<const Action*> actionsOf(const MachineState& state) {
    std::vector<const Action*> list;
    std::transform(state.actions.begin(), state.actions.end(), std::back_inserter(list),
                   [](const Action& action) { return &action; });
    return list;
}

bool allTrue(const std::vector<Condition>& when, const Table& table) {
    return std::all_of(when.begin(), when.end(), [&](const Condition& c) { return table.at(c.type); });
}

int referenceStep(const StateMachine& machine, int current, const Table& table, std::vector<const Action*>& actions) {
    const std::vector<Transition>& list = machine.states[static_cast<std::size_t>(current)].transitions;
    const auto fired = std::find_if(list.begin(), list.end(), [&](const Transition& t) { return allTrue(t.when, table); });
    const int next = fired == list.end() ? current : fired->target;
    actions = actionsOf(machine.states[static_cast<std::size_t>(next)]);
    return next;
}

int referenceLayer(const SubsumptionStack& stack, const Table& table) {
    const auto fired = std::find_if(stack.layers.begin(), stack.layers.end(),
                                    [&](const Layer& layer) { return allTrue(layer.when, table); });
    return fired == stack.layers.end() ? -1 : static_cast<int>(fired - stack.layers.begin());
}

SubsumptionStack stackOf(const std::vector<std::vector<std::string>>& layers) {
    SubsumptionStack stack;
    for (const auto& when : layers) {
        Layer layer;
        layer.name = "layer" + std::to_string(stack.layers.size());
        layer.when = conditions(when);
        stack.layers.push_back(layer);
    }
    return stack;
}

const Action kStale{};   // what `actions` holds before a call, to see that it is cleared

// The ground: grids, and the references in double.

struct Point {
    double x, z;
};

CollisionMap collisionMap(int width, int height, glm::vec2 min, glm::vec2 max, std::vector<std::uint8_t> walkable) {
    CollisionMap map;
    map.grid = {width, height, min, max};
    map.walkable = std::move(walkable);
    return map;
}

/// The texel whose half-open cell [x0, x0 + cell) x [z0, z0 + cell) holds the point.
bool referenceWalkable(const CollisionMap& map, double x, double z) {
    const GroundGrid& g = map.grid;
    const double cellX = (static_cast<double>(g.footprintMax.x) - g.footprintMin.x) / g.width;
    const double cellZ = (static_cast<double>(g.footprintMax.y) - g.footprintMin.y) / g.height;
    for (int row = 0; row < g.height; ++row) {
        const double z0 = g.footprintMin.y + row * cellZ;
        if (z < z0 || z >= z0 + cellZ) continue;
        for (int col = 0; col < g.width; ++col) {
            const double x0 = g.footprintMin.x + col * cellX;
            if (x >= x0 && x < x0 + cellX) return map.walkable[static_cast<std::size_t>(row * g.width + col)] != 0;
        }
    }
    return false;
}

/// How far (in texels) the point lies from the nearest texel edge along either axis.
double distanceToTexelEdge(const GroundGrid& g, double x, double z) {
    const double u = (x - g.footprintMin.x) / (static_cast<double>(g.footprintMax.x) - g.footprintMin.x) * g.width;
    const double v = (z - g.footprintMin.y) / (static_cast<double>(g.footprintMax.y) - g.footprintMin.y) * g.height;
    return std::min(std::abs(u - std::round(u)), std::abs(v - std::round(v)));
}

/// Bilinear as a sum of tent weights: sample (col, row) at its texel centre
/// weighs max(0, 1 - |u - col|) * max(0, 1 - |v - row|) in clamped texel units.
double referenceHeight(const HeightField& field, double x, double z) {
    const GroundGrid& g = field.grid;
    const double sizeX = static_cast<double>(g.footprintMax.x) - g.footprintMin.x;
    const double sizeZ = static_cast<double>(g.footprintMax.y) - g.footprintMin.y;
    const double u = std::clamp((x - g.footprintMin.x) * g.width / sizeX - 0.5, 0.0, g.width - 1.0);
    const double v = std::clamp((z - g.footprintMin.y) * g.height / sizeZ - 0.5, 0.0, g.height - 1.0);
    double value = 0.0;
    for (int row = 0; row < g.height; ++row) {
        for (int col = 0; col < g.width; ++col) {
            const double weight = std::max(0.0, 1.0 - std::abs(u - col)) * std::max(0.0, 1.0 - std::abs(v - row));
            value += weight * field.values[static_cast<std::size_t>(row * g.width + col)];
        }
    }
    return field.heightMin + (static_cast<double>(field.heightMax) - field.heightMin) * value;
}

Point texelCentre(const GroundGrid& g, int col, int row) {
    const double cellX = (static_cast<double>(g.footprintMax.x) - g.footprintMin.x) / g.width;
    const double cellZ = (static_cast<double>(g.footprintMax.y) - g.footprintMin.y) / g.height;
    return {g.footprintMin.x + (col + 0.5) * cellX, g.footprintMin.y + (row + 0.5) * cellZ};
}

/// 7 x 5 texels of 2 m x 1 m over [-3, 11] x [1, 6], random values, heights -2 .. 5.
HeightField testField(std::uint32_t seed) {
    test::Random random(seed);
    HeightField field;
    field.grid = {7, 5, {-3.0f, 1.0f}, {11.0f, 6.0f}};
    for (int i = 0; i < 7 * 5; ++i) field.values.push_back(random.uniform(0.0f, 1.0f));
    field.heightMin = -2.0f;
    field.heightMax = 5.0f;
    return field;
}

float heightAtPoint(const HeightField& field, Point p) {
    return heightAt(field, glm::vec2(static_cast<float>(p.x), static_cast<float>(p.z)));
}

// Key frames.

struct ReferencePair {
    int first, second;
    double t;
};

ReferencePair referenceFrames(const Md2Animation& animation, double seconds, double framesPerSecond) {
    double phase = std::fmod(seconds * framesPerSecond, static_cast<double>(animation.count));
    if (phase < 0.0) phase += animation.count;
    const int k = std::min(static_cast<int>(phase), animation.count - 1);
    const int next = k + 1 == animation.count ? 0 : k + 1;
    return {animation.first + k, animation.first + next, phase - k};
}

/// Where on the loop a pair puts the pose, in frames from the animation's
/// first: k + t. Two pairs agree when these are close around the loop.
double loopDistance(const Md2Animation& animation, double a, double b) {
    const double d = std::fmod(std::abs(a - b), static_cast<double>(animation.count));
    return std::min(d, animation.count - d);
}

std::string describe(const Md2FramePair& pair) {
    std::ostringstream out;
    out.precision(9);
    out << "{first " << pair.first << ", second " << pair.second << ", t " << pair.t << "}";
    return out.str();
}

void requireValidPair(const Md2Animation& animation, const Md2FramePair& pair) {
    INFO(describe(pair));
    REQUIRE(pair.first >= animation.first);
    REQUIRE(pair.first < animation.first + animation.count);
    REQUIRE(pair.second == animation.first + (pair.first - animation.first + 1) % animation.count);
    REQUIRE(pair.t >= 0.0f);
    REQUIRE(pair.t < 1.0f);
}

Md2Frame randomFrame(test::Random& random, int vertices) {
    Md2Frame frame;
    for (int i = 0; i < vertices; ++i) {
        frame.positions.push_back(random.inBox(glm::vec3(-20.0f), glm::vec3(20.0f)));
        frame.normals.push_back(random.unitVector());
    }
    return frame;
}

double distance(const glm::vec3& a, const glm::dvec3& b) { return glm::length(glm::dvec3(a) - b); }

std::string readBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

// stepStateMachine

TEST_CASE("Lab 10: stepStateMachine fires the first transition that holds, not a later one", "[lab10][crowds]") {
    StateMachine machine;
    machine.states = {machineState({transition({"a"}, 1), transition({"b"}, 2), transition({"c"}, 3)}, 1, 100),
                      machineState({}, 1, 200), machineState({}, 2, 300), machineState({}, 3, 400)};
    std::vector<const Action*> actions;
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", false}, {"b", true}, {"c", true}}), actions) == 2);
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", true}, {"b", true}, {"c", true}}), actions) == 1);
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", false}, {"b", false}, {"c", true}}), actions) == 3);
}

TEST_CASE("Lab 10: stepStateMachine fires a transition only when all its conditions hold", "[lab10][crowds]") {
    StateMachine machine;
    machine.states = {machineState({transition({"a", "b"}, 1), transition({"b", "a"}, 2), transition({"c", "a", "b"}, 3),
                                    transition({}, 4)},
                                   0, 100),
                      machineState({}, 0, 200), machineState({}, 0, 300), machineState({}, 0, 400),
                      machineState({}, 0, 500)};
    std::vector<const Action*> actions;
    // One of the two holds, in either order: neither transition fires.
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", true}, {"b", false}, {"c", true}}), actions) == 4);
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", false}, {"b", true}, {"c", true}}), actions) == 4);
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", true}, {"b", true}, {"c", true}}), actions) == 1);
    // `negated` is the senses' business: a negated condition the senses answer true holds.
    machine.states[0].transitions[0].when = {condition("a", true), condition("b", true)};
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", true}, {"b", true}, {"c", false}}), actions) == 1);
}

TEST_CASE("Lab 10: stepStateMachine fires a transition with no conditions", "[lab10][crowds]") {
    StateMachine machine;
    machine.states = {machineState({transition({}, 1)}, 1, 100), machineState({transition({"a"}, 0)}, 2, 200)};
    std::vector<const Action*> actions;
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", false}}), actions) == 1);
    CHECK(actions == actionsOf(machine.states[1]));
}

TEST_CASE("Lab 10: stepStateMachine keeps the state, and runs its actions, when no transition fires", "[lab10][crowds]") {
    StateMachine machine;
    machine.states = {machineState({transition({"a"}, 1), transition({"a", "b"}, 2)}, 3, 100),
                      machineState({}, 1, 200), machineState({}, 1, 300)};
    std::vector<const Action*> actions{&kStale, &kStale, &kStale, &kStale, &kStale};
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", false}, {"b", true}}), actions) == 0);
    CHECK(actions == actionsOf(machine.states[0]));
    // A state without transitions stays too.
    CHECK(stepStateMachine(machine, 2, TableSenses({}), actions) == 2);
    CHECK(actions == actionsOf(machine.states[2]));
}

TEST_CASE("Lab 10: stepStateMachine's actions are the new state's, in their order, `actions` cleared first",
          "[lab10][crowds]") {
    StateMachine machine;
    machine.states = {machineState({transition({"a"}, 1)}, 2, 100), machineState({transition({"b"}, 2)}, 3, 200),
                      machineState({transition({"c"}, 0)}, 0, 300)};
    std::vector<const Action*> actions{&kStale, &kStale};
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", true}}), actions) == 1);
    REQUIRE(actions.size() == 3);
    CHECK(actions[0]->line == 200);
    CHECK(actions[1]->line == 201);
    CHECK(actions[2]->line == 202);
    CHECK(actions == actionsOf(machine.states[1]));   // pointers into the machine, not copies
    // Into a state without actions: the list ends empty.
    CHECK(stepStateMachine(machine, 1, TableSenses({{"b", true}}), actions) == 2);
    CHECK(actions.empty());
    // A transition back to the state itself still gives that state's actions once.
    machine.states[0].transitions = {transition({"a"}, 0)};
    actions.assign(7, &kStale);
    CHECK(stepStateMachine(machine, 0, TableSenses({{"a", true}}), actions) == 0);
    CHECK(actions == actionsOf(machine.states[0]));
}

TEST_CASE("Lab 10: stepStateMachine agrees with the reference on 2,000 random machines", "[lab10][crowds]") {
    test::Random random(1010);
    const std::vector<std::string> names{"a", "b", "c", "d", "e"};
    int moved = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        StateMachine machine;
        const int states = 1 + random.below(6);
        for (int s = 0; s < states; ++s) {
            std::vector<Transition> transitions;
            for (int k = random.below(5); k > 0; --k) {
                std::vector<std::string> when;
                for (int c = random.below(4); c > 0; --c) when.push_back(names[static_cast<std::size_t>(random.below(5))]);
                transitions.push_back(transition(when, random.below(states)));
            }
            machine.states.push_back(machineState(transitions, random.below(4), 100 * (s + 1)));
        }
        Table table;
        for (const std::string& name : names) table[name] = random.chance(0.6f);
        const int current = random.below(states);
        std::vector<const Action*> expected;
        const int want = referenceStep(machine, current, table, expected);
        std::vector<const Action*> actions(static_cast<std::size_t>(random.below(3)), &kStale);
        INFO("trial " << trial << ", from state " << current);
        REQUIRE(stepStateMachine(machine, current, TableSenses(table), actions) == want);
        REQUIRE(actions == expected);
        moved += want != current;
    }
    CHECK(moved > 400);   // the cases exercise both outcomes
}

// arbitrateLayers

TEST_CASE("Lab 10: arbitrateLayers picks the first layer from the top that fires", "[lab10][crowds]") {
    const SubsumptionStack stack = stackOf({{"a"}, {"b"}, {"c"}, {}});
    CHECK(arbitrateLayers(stack, TableSenses({{"a", true}, {"b", true}, {"c", true}})) == 0);
    CHECK(arbitrateLayers(stack, TableSenses({{"a", false}, {"b", true}, {"c", true}})) == 1);
    CHECK(arbitrateLayers(stack, TableSenses({{"a", false}, {"b", false}, {"c", true}})) == 2);
}

TEST_CASE("Lab 10: arbitrateLayers: a layer without conditions always fires; all conditions must hold",
          "[lab10][crowds]") {
    CHECK(arbitrateLayers(stackOf({{"a"}, {}}), TableSenses({{"a", false}})) == 1);
    CHECK(arbitrateLayers(stackOf({{}, {"a"}}), TableSenses({{"a", true}})) == 0);
    const SubsumptionStack stack = stackOf({{"a", "b"}, {"b", "a"}, {}});
    CHECK(arbitrateLayers(stack, TableSenses({{"a", true}, {"b", false}})) == 2);
    CHECK(arbitrateLayers(stack, TableSenses({{"a", false}, {"b", true}})) == 2);
    CHECK(arbitrateLayers(stack, TableSenses({{"a", true}, {"b", true}})) == 0);
}

TEST_CASE("Lab 10: arbitrateLayers returns -1 when no layer fires, or there is none", "[lab10][crowds]") {
    CHECK(arbitrateLayers(stackOf({{"a"}, {"b"}, {"a", "b"}}), TableSenses({{"a", false}, {"b", false}})) == -1);
    CHECK(arbitrateLayers(SubsumptionStack{}, TableSenses({})) == -1);
}

TEST_CASE("Lab 10: arbitrateLayers agrees with the reference on 2,000 random stacks", "[lab10][crowds]") {
    test::Random random(2020);
    const std::vector<std::string> names{"a", "b", "c", "d"};
    int none = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<std::vector<std::string>> layers(static_cast<std::size_t>(random.below(6)));
        for (auto& when : layers)
            for (int c = random.below(4); c > 0; --c) when.push_back(names[static_cast<std::size_t>(random.below(4))]);
        Table table;
        for (const std::string& name : names) table[name] = random.chance(0.5f);
        const SubsumptionStack stack = stackOf(layers);
        const int want = referenceLayer(stack, table);
        INFO("trial " << trial);
        REQUIRE(arbitrateLayers(stack, TableSenses(table)) == want);
        none += want < 0;
    }
    CHECK(none > 50);
    CHECK(none < 1500);
}

// walkableAt

TEST_CASE("Lab 10: walkableAt: row 0 lies along z = footprintMin.y, column 0 along x = footprintMin.x",
          "[lab10][crowds]") {
    // 2 x 2 texels over [0, 4] x [10, 14]: only row 0 walkable, then only column 0.
    CollisionMap rows = collisionMap(2, 2, {0.0f, 10.0f}, {4.0f, 14.0f}, {1, 1, 0, 0});
    CHECK(walkableAt(rows, {1.0f, 10.1f}));
    CHECK(walkableAt(rows, {3.0f, 11.9f}));
    CHECK_FALSE(walkableAt(rows, {1.0f, 12.1f}));
    CHECK_FALSE(walkableAt(rows, {3.0f, 13.9f}));
    CollisionMap columns = collisionMap(2, 2, {0.0f, 10.0f}, {4.0f, 14.0f}, {1, 0, 1, 0});
    CHECK(walkableAt(columns, {0.1f, 11.0f}));
    CHECK(walkableAt(columns, {1.9f, 13.0f}));
    CHECK_FALSE(walkableAt(columns, {2.1f, 11.0f}));
    CHECK_FALSE(walkableAt(columns, {3.9f, 13.0f}));
}

TEST_CASE("Lab 10: walkableAt at every texel corner and centre of a non-square map over a non-square footprint",
          "[lab10][crowds]") {
    // 16 x 4 texels of 1 m x 2 m over [-4, 12] x [2, 10]: powers of two, so a
    // corner lands exactly on its texel's edge in float as in double.
    const int width = 16, height = 4;
    std::vector<std::uint8_t> walkable;
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) walkable.push_back((col * 7 + row * 3) % 5 < 2 ? 1 : 0);
    const CollisionMap map = collisionMap(width, height, {-4.0f, 2.0f}, {12.0f, 10.0f}, walkable);
    int checked = 0;
    for (int row = 0; row <= height; ++row) {
        for (int col = 0; col <= width; ++col) {
            const double x = -4.0 + col * 1.0, z = 2.0 + row * 2.0;
            const bool corner = col < width && row < height && walkable[static_cast<std::size_t>(row * width + col)];
            INFO("corner of texel (" << col << ", " << row << ") at (" << x << ", " << z << ")");
            REQUIRE(referenceWalkable(map, x, z) == corner);
            REQUIRE(walkableAt(map, {static_cast<float>(x), static_cast<float>(z)}) == corner);
            // Just inside each texel that meets at this corner.
            for (const auto& offset : {Point{0.01, 0.02}, Point{-0.01, 0.02}, Point{0.01, -0.02}, Point{-0.01, -0.02}}) {
                const double px = x + offset.x, pz = z + offset.z;
                INFO("at (" << px << ", " << pz << ")");
                REQUIRE(walkableAt(map, {static_cast<float>(px), static_cast<float>(pz)}) ==
                        referenceWalkable(map, px, pz));
                ++checked;
            }
            if (col < width && row < height) {
                const Point centre = texelCentre(map.grid, col, row);
                REQUIRE(walkableAt(map, {static_cast<float>(centre.x), static_cast<float>(centre.z)}) == corner);
            }
        }
    }
    CHECK(checked == 4 * (width + 1) * (height + 1));
}

TEST_CASE("Lab 10: walkableAt is false outside the footprint, and on its far edges", "[lab10][crowds]") {
    const CollisionMap map = collisionMap(4, 2, {-2.0f, -1.0f}, {2.0f, 3.0f}, std::vector<std::uint8_t>(8, 1));
    CHECK(walkableAt(map, {-2.0f, -1.0f}));   // the near corner belongs to texel (0, 0)
    CHECK(walkableAt(map, {1.99f, 2.99f}));
    for (const glm::vec2 p : {glm::vec2(-2.01f, 0.0f), glm::vec2(2.0f, 0.0f), glm::vec2(2.5f, 0.0f), glm::vec2(0.0f, -1.01f),
                              glm::vec2(0.0f, 3.0f), glm::vec2(0.0f, 30.0f), glm::vec2(-100.0f, -100.0f),
                              glm::vec2(2.0f, 3.0f), glm::vec2(-3.0f, 4.0f)}) {
        INFO("at (" << p.x << ", " << p.y << ")");
        CHECK_FALSE(walkableAt(map, p));
    }
}

TEST_CASE("Lab 10: walkableAt agrees with the reference on random points of a 64 x 48 map", "[lab10][crowds]") {
    test::Random random(3030);
    const int width = 64, height = 48;
    std::vector<std::uint8_t> walkable;
    for (int i = 0; i < width * height; ++i) walkable.push_back(random.chance(0.5f) ? 1 : 0);
    const CollisionMap map = collisionMap(width, height, {-15.0f, -15.0f}, {15.0f, 15.0f}, walkable);
    int compared = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec2 p(random.uniform(-16.0f, 16.0f), random.uniform(-16.0f, 16.0f));
        if (distanceToTexelEdge(map.grid, p.x, p.y) < 1e-4) continue;
        INFO("at (" << p.x << ", " << p.y << ")");
        REQUIRE(walkableAt(map, p) == referenceWalkable(map, p.x, p.y));
        ++compared;
    }
    CHECK(compared > 19800);
}

// heightAt

TEST_CASE("Lab 10: heightAt is the texel's value at its centre, mapped to [heightMin, heightMax]", "[lab10][crowds]") {
    const HeightField field = testField(4040);
    for (int row = 0; row < field.grid.height; ++row) {
        for (int col = 0; col < field.grid.width; ++col) {
            const double value = field.values[static_cast<std::size_t>(row * field.grid.width + col)];
            const double want = -2.0 + 7.0 * value;
            INFO("texel (" << col << ", " << row << ")");
            CHECK(std::abs(heightAtPoint(field, texelCentre(field.grid, col, row)) - want) < 1e-5);
        }
    }
}

TEST_CASE("Lab 10: heightAt midway between four texel centres is their mean", "[lab10][crowds]") {
    const HeightField field = testField(5050);
    const auto value = [&](int col, int row) { return field.values[static_cast<std::size_t>(row * field.grid.width + col)]; };
    for (int row = 0; row + 1 < field.grid.height; ++row) {
        for (int col = 0; col + 1 < field.grid.width; ++col) {
            const Point a = texelCentre(field.grid, col, row), b = texelCentre(field.grid, col + 1, row + 1);
            const double mean = 0.25 * (value(col, row) + value(col + 1, row) + value(col, row + 1) + value(col + 1, row + 1));
            INFO("between texels (" << col << ", " << row << ") and (" << col + 1 << ", " << row + 1 << ")");
            CHECK(std::abs(heightAtPoint(field, {0.5 * (a.x + b.x), 0.5 * (a.z + b.z)}) - (-2.0 + 7.0 * mean)) < 1e-5);
            // A quarter of the way along x on row `row`'s centre line.
            const double along = 0.75 * value(col, row) + 0.25 * value(col + 1, row);
            CHECK(std::abs(heightAtPoint(field, {0.75 * a.x + 0.25 * b.x, a.z}) - (-2.0 + 7.0 * along)) < 1e-5);
        }
    }
}

TEST_CASE("Lab 10: heightAt agrees with the reference in and around the footprint", "[lab10][crowds]") {
    for (const std::uint32_t seed : {6060u, 6061u}) {
        const HeightField field = testField(seed);
        test::Random random(seed);
        for (int i = 0; i < 5000; ++i) {
            const glm::vec2 p(random.uniform(-7.0f, 15.0f), random.uniform(-1.0f, 8.0f));
            INFO("seed " << seed << ", at (" << p.x << ", " << p.y << ")");
            REQUIRE(std::abs(heightAt(field, p) - referenceHeight(field, p.x, p.y)) < 2e-5);
        }
    }
    // A square field over a square footprint, as the example worlds have.
    HeightField square;
    square.grid = {64, 64, {-30.0f, -30.0f}, {30.0f, 30.0f}};
    test::Random random(6062);
    for (int i = 0; i < 64 * 64; ++i) square.values.push_back(random.uniform(0.0f, 1.0f));
    square.heightMax = 6.0f;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec2 p(random.uniform(-31.0f, 31.0f), random.uniform(-31.0f, 31.0f));
        INFO("at (" << p.x << ", " << p.y << ")");
        REQUIRE(std::abs(heightAt(square, p) - referenceHeight(square, p.x, p.y)) < 2e-5);
    }
}

TEST_CASE("Lab 10: heightAt is clamped to the edge texels outside their centres", "[lab10][crowds]") {
    const HeightField field = testField(7070);
    const GroundGrid& g = field.grid;
    const auto height = [&](int col, int row) {
        return -2.0 + 7.0 * field.values[static_cast<std::size_t>(row * g.width + col)];
    };
    for (int row = 0; row < g.height; ++row) {
        const double z = texelCentre(g, 0, row).z;
        for (const double x : {-3.0, -2.5, -50.0}) CHECK(std::abs(heightAtPoint(field, {x, z}) - height(0, row)) < 1e-5);
        for (const double x : {11.0, 10.5, 50.0})
            CHECK(std::abs(heightAtPoint(field, {x, z}) - height(g.width - 1, row)) < 1e-5);
    }
    for (int col = 0; col < g.width; ++col) {
        const double x = texelCentre(g, col, 0).x;
        for (const double z : {1.0, 1.25, -40.0}) CHECK(std::abs(heightAtPoint(field, {x, z}) - height(col, 0)) < 1e-5);
        for (const double z : {6.0, 5.75, 40.0})
            CHECK(std::abs(heightAtPoint(field, {x, z}) - height(col, g.height - 1)) < 1e-5);
    }
    CHECK(std::abs(heightAtPoint(field, {-9.0, -9.0}) - height(0, 0)) < 1e-5);
    CHECK(std::abs(heightAtPoint(field, {99.0, 99.0}) - height(g.width - 1, g.height - 1)) < 1e-5);
    CHECK(std::abs(heightAtPoint(field, {99.0, -9.0}) - height(g.width - 1, 0)) < 1e-5);
}

TEST_CASE("Lab 10: heightAt maps values 0 and 1 to heightMin and heightMax", "[lab10][crowds]") {
    HeightField field;
    field.grid = {2, 2, {0.0f, 0.0f}, {2.0f, 2.0f}};
    field.values = {0.0f, 1.0f, 0.25f, 0.75f};
    field.heightMin = 3.0f;
    field.heightMax = 11.0f;
    CHECK(heightAt(field, {0.5f, 0.5f}) == Approx(3.0));
    CHECK(heightAt(field, {1.5f, 0.5f}) == Approx(11.0));
    CHECK(heightAt(field, {0.5f, 1.5f}) == Approx(5.0));
    CHECK(heightAt(field, {1.5f, 1.5f}) == Approx(9.0));
    CHECK(heightAt(field, {1.0f, 1.0f}) == Approx(7.0));
    field.heightMin = -4.0f;
    field.heightMax = -4.0f;
    CHECK(heightAt(field, {1.3f, 0.2f}) == Approx(-4.0));
}

TEST_CASE("Lab 10: heightAt on a 1 x 1 field is its one value everywhere", "[lab10][crowds]") {
    HeightField field;
    field.grid = {1, 1, {-15.0f, -15.0f}, {15.0f, 15.0f}};
    field.values = {0.4f};
    field.heightMin = 1.0f;
    field.heightMax = 3.0f;
    for (const glm::vec2 p : {glm::vec2(0.0f), glm::vec2(-15.0f), glm::vec2(14.9f, -3.0f), glm::vec2(40.0f, -70.0f)})
        CHECK(heightAt(field, p) == Approx(1.8));
    field.values = {0.0f};   // what loadGroundMaps gives a world without a height map
    field.heightMin = field.heightMax = 0.0f;
    CHECK(heightAt(field, {3.0f, 4.0f}) == 0.0f);
}

// md2FramesAt

TEST_CASE("Lab 10: md2FramesAt shows frame k at k / fps seconds", "[lab10][crowds]") {
    const Md2Animation run{"run", 10, 6};
    for (int k = 0; k < 6; ++k) {
        const Md2FramePair pair = md2FramesAt(run, static_cast<float>(k) / 8.0f, 8.0f);
        INFO("k " << k << ": " << describe(pair));
        CHECK(pair.first == 10 + k);
        CHECK(pair.second == 10 + (k + 1) % 6);
        CHECK(pair.t == 0.0f);
    }
    // At 10 frames per second k / 10 is not exact in float: frame k, or k - 1 with t near 1.
    for (int k = 0; k < 6; ++k) {
        const Md2FramePair pair = md2FramesAt(run, static_cast<float>(k) / 10.0f, 10.0f);
        INFO("k " << k << ": " << describe(pair));
        requireValidPair(run, pair);
        CHECK(loopDistance(run, pair.first - run.first + pair.t, k) < 1e-5);
    }
    const Md2FramePair between = md2FramesAt(run, 2.5f / 8.0f, 8.0f);
    CHECK(between.first == 12);
    CHECK(between.second == 13);
    CHECK(between.t == Approx(0.5));
}

TEST_CASE("Lab 10: md2FramesAt: the last frame blends into the animation's own first", "[lab10][crowds]") {
    const Md2Animation run{"run", 10, 6};
    const Md2FramePair pair = md2FramesAt(run, 5.5f / 8.0f, 8.0f);
    INFO(describe(pair));
    CHECK(pair.first == 15);
    CHECK(pair.second == 10);
    CHECK(pair.t == Approx(0.5));
    const Md2FramePair loop = md2FramesAt(run, 6.0f / 8.0f, 8.0f);   // a whole loop: frame 0 again
    CHECK(loop.first == 10);
    CHECK(loop.second == 11);
    CHECK(loop.t == 0.0f);
}

TEST_CASE("Lab 10: md2FramesAt after a thousand loops", "[lab10][crowds]") {
    const Md2Animation run{"run", 10, 6};
    // (6000 + 2.25) / 8 = 750.28125 s, exact in float.
    const Md2FramePair pair = md2FramesAt(run, 750.28125f, 8.0f);
    INFO(describe(pair));
    CHECK(pair.first == 12);
    CHECK(pair.second == 13);
    CHECK(pair.t == Approx(0.25));
    const Md2FramePair last = md2FramesAt(run, (5994.0f + 5.75f) / 8.0f, 8.0f);
    INFO(describe(last));
    CHECK(last.first == 15);
    CHECK(last.second == 10);
    CHECK(last.t == Approx(0.75));
}

TEST_CASE("Lab 10: md2FramesAt on a one-frame animation stays on it", "[lab10][crowds]") {
    const Md2Animation pose{"pose", 3, 1};
    for (const float seconds : {0.0f, 0.01f, 0.125f, 0.3f, 1.0f, 17.77f, 1234.5f}) {
        const Md2FramePair pair = md2FramesAt(pose, seconds, 8.0f);
        INFO("at " << seconds << " s: " << describe(pair));
        CHECK(pair.first == 3);
        CHECK(pair.second == 3);
        CHECK(pair.t >= 0.0f);
        CHECK(pair.t < 1.0f);
    }
}

TEST_CASE("Lab 10: md2FramesAt's indices are offset by animation.first", "[lab10][crowds]") {
    for (const float seconds : {0.0f, 0.2f, 0.61f, 0.99f, 3.3f}) {
        const Md2FramePair atZero = md2FramesAt({"a", 0, 5}, seconds, 9.0f);
        const Md2FramePair atForty = md2FramesAt({"b", 40, 5}, seconds, 9.0f);
        INFO("at " << seconds << " s: " << describe(atZero) << " and " << describe(atForty));
        CHECK(atForty.first == atZero.first + 40);
        CHECK(atForty.second == atZero.second + 40);
        CHECK(atForty.t == atZero.t);
        CHECK(atForty.first >= 40);
        CHECK(atForty.first < 45);
    }
}

TEST_CASE("Lab 10: md2FramesAt's t is at least 0 and below 1, also just below a loop's end", "[lab10][crowds]") {
    const Md2Animation run{"run", 7, 6};
    for (int i = 0; i < 20000; ++i) requireValidPair(run, md2FramesAt(run, static_cast<float>(i) * 0.00731f, 8.0f));
    for (int loops = 1; loops < 2000; loops += 37) {
        for (const float fps : {8.0f, 9.0f, 10.0f, 24.0f}) {
            const float end = static_cast<float>(loops) * 6.0f / fps;
            const float below = std::nextafter(end, 0.0f);
            INFO(loops << " loops at " << fps << " fps, " << below << " s");
            requireValidPair(run, md2FramesAt(run, below, fps));
            requireValidPair(run, md2FramesAt(run, end, fps));
        }
    }
}

TEST_CASE("Lab 10: md2FramesAt agrees with the reference on 5,000 random cases", "[lab10][crowds]") {
    test::Random random(8080);
    for (int i = 0; i < 5000; ++i) {
        const Md2Animation animation{"x", random.below(200), 1 + random.below(40)};
        const float fps = random.uniform(1.0f, 30.0f);
        const float seconds = random.uniform(0.0f, 500.0f);
        const Md2FramePair pair = md2FramesAt(animation, seconds, fps);
        const ReferencePair want = referenceFrames(animation, seconds, fps);
        INFO("animation first " << animation.first << " count " << animation.count << ", " << seconds << " s at "
                                << fps << " fps: " << describe(pair) << ", want first " << want.first << " t "
                                << want.t);
        requireValidPair(animation, pair);
        // float's product seconds * fps is off by up to about 1e-7 of it.
        const double tolerance = 4e-7 * seconds * fps + 1e-6;
        REQUIRE(loopDistance(animation, pair.first - animation.first + pair.t, want.first - animation.first + want.t) <
                tolerance);
    }
}

// blendMd2Frames

TEST_CASE("Lab 10: blendMd2Frames at t = 0 and t = 1 gives the frames", "[lab10][crowds]") {
    test::Random random(9090);
    const Md2Frame a = randomFrame(random, 60), b = randomFrame(random, 60);
    std::vector<glm::vec3> positions, normals;
    blendMd2Frames(a, b, 0.0f, positions, normals);
    REQUIRE(positions.size() == 60);
    REQUIRE(normals.size() == 60);
    for (std::size_t i = 0; i < 60; ++i) {
        CHECK(distance(positions[i], glm::dvec3(a.positions[i])) < 1e-5);
        CHECK(distance(normals[i], glm::dvec3(a.normals[i])) < 1e-5);
    }
    blendMd2Frames(a, b, 1.0f, positions, normals);
    for (std::size_t i = 0; i < 60; ++i) {
        CHECK(distance(positions[i], glm::dvec3(b.positions[i])) < 1e-5);
        CHECK(distance(normals[i], glm::dvec3(b.normals[i])) < 1e-5);
    }
}

TEST_CASE("Lab 10: blendMd2Frames mixes positions and gives normals of unit length along the mix", "[lab10][crowds]") {
    Md2Frame a, b;
    a.positions = {{0.0f, 0.0f, 0.0f}};
    b.positions = {{2.0f, -4.0f, 8.0f}};
    a.normals = {{1.0f, 0.0f, 0.0f}};
    b.normals = {{0.0f, 1.0f, 0.0f}};
    std::vector<glm::vec3> positions, normals;
    blendMd2Frames(a, b, 0.5f, positions, normals);
    REQUIRE(normals.size() == 1);
    CHECK(distance(positions[0], {1.0, -2.0, 4.0}) < 1e-6);
    CHECK(distance(normals[0], {std::sqrt(0.5), std::sqrt(0.5), 0.0}) < 1e-6);

    test::Random random(9191);
    int compared = 0;
    for (int trial = 0; trial < 20; ++trial) {
        const Md2Frame first = randomFrame(random, 100), second = randomFrame(random, 100);
        const float t = random.uniform(0.0f, 1.0f);
        blendMd2Frames(first, second, t, positions, normals);
        for (std::size_t i = 0; i < 100; ++i) {
            const glm::dvec3 p = glm::dvec3(first.positions[i]) * (1.0 - t) + glm::dvec3(second.positions[i]) * double(t);
            const glm::dvec3 n = glm::dvec3(first.normals[i]) * (1.0 - t) + glm::dvec3(second.normals[i]) * double(t);
            INFO("trial " << trial << ", vertex " << i << ", t " << t);
            REQUIRE(distance(positions[i], p) < 2e-5);
            if (glm::length(n) < 0.1) continue;   // nearly opposite normals: any direction will do
            REQUIRE(std::abs(glm::length(glm::dvec3(normals[i])) - 1.0) < 1e-5);
            REQUIRE(distance(normals[i], glm::normalize(n)) < 1e-4);
            ++compared;
        }
    }
    CHECK(compared > 1800);
}

TEST_CASE("Lab 10: blendMd2Frames resizes its outputs to the frame's vertex count", "[lab10][crowds]") {
    test::Random random(9292);
    const Md2Frame a = randomFrame(random, 37), b = randomFrame(random, 37);
    std::vector<glm::vec3> positions(500, glm::vec3(9.0f)), normals(3, glm::vec3(9.0f));
    blendMd2Frames(a, b, 0.25f, positions, normals);
    CHECK(positions.size() == 37);
    CHECK(normals.size() == 37);
    positions.clear();
    normals.assign(80, glm::vec3(0.0f));
    blendMd2Frames(a, b, 0.75f, positions, normals);
    CHECK(positions.size() == 37);
    CHECK(normals.size() == 37);
    const Md2Frame none;
    blendMd2Frames(none, none, 0.5f, positions, normals);
    CHECK(positions.empty());
    CHECK(normals.empty());
}

// The maps the example worlds use.

TEST_CASE("Lab 10: writeExampleGroundMaps writes exactly the committed maps", "[lab10][crowds]") {
    const test::TempFolder folder("crowd-maps");
    const std::vector<std::filesystem::path> written = writeExampleGroundMaps(folder.path());
    std::vector<std::string> names;
    for (const std::filesystem::path& path : written) names.push_back(path.filename().string());
    std::sort(names.begin(), names.end());
    CHECK(names == std::vector<std::string>{"acropolis_collision.png", "hills_collision.png", "hills_height.png"});
    for (const std::filesystem::path& path : written) {
        const std::filesystem::path committed = paths::assetsDir() / "crowds" / path.filename();
        INFO(path.filename().string() << " against " << committed.string());
        REQUIRE(std::filesystem::exists(committed));
        CHECK(readBytes(path) == readBytes(committed));
    }
}
