// Lab 10's behaviour functions (labs/10_crowds/student/lab10.hpp) against
// independent references written here:
//   - stepStateMachine and arbitrateLayers, asked through a fake CrowdSenses
//     that answers every condition from a table (keyed by the condition's
//     `type`: the tests name their conditions "a", "b", ...): the first
//     transition whose conditions all hold fires, an empty list fires, none
//     firing keeps the state, the actions are the new state's in their order,
//     `actions` is cleared first, `negated` is left to the senses; the first
//     layer from the top fires, a layer without conditions always does, -1 when
//     none does; then both against a reference (std::find_if over std::all_of)
//     on 2,000 random machines and stacks with random tables.
// The planted mistakes of solutions/10_crowds/mistakes/ for these functions each
// fail cases here (checked by applying each one's find/replace to a copy of the solution):
//   any_condition_fires        stepStateMachine "all its conditions", "keeps the state", random
//                              machines; arbitrateLayers "all conditions must hold", random stacks
//   transitions_after_actions  stepStateMachine "no conditions", "the new state's", random machines
//   layers_reversed            arbitrateLayers "first from the top", "all conditions", random stacks
// GroundTests.cpp tests the lab's ground, Md2BlendTests.cpp its key frames.

#include "catch.hpp"
#include "TestRandom.hpp"
#include "lab10.hpp"

#include <stoa/crowd/CrowdLab.hpp>

#include <algorithm>
#include <iterator>
#include <map>
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
