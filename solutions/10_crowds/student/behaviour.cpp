// Lab 10, part 1: how an agent decides. Read docs/labs/10_crowds.md, "Finite
// state machines" and "Subsumption", first. The simulation calls one of the two
// for every agent at every step, with its senses of that step.

#include "lab10.hpp"

#include <stoa/crowd/CrowdLab.hpp>

namespace stoa {

namespace {

bool allHold(const std::vector<Condition>& conditions, const CrowdSenses& senses) {
    for (const Condition& condition : conditions)
        if (!senses.holds(condition)) return false;
    return true;
}

} // namespace

int stepStateMachine(const StateMachine& machine, int current, const CrowdSenses& senses,
                     std::vector<const Action*>& actions) {
    // The transitions first, in their order: the first that holds fires.
    int next = current;
    for (const Transition& transition : machine.states[static_cast<std::size_t>(current)].transitions) {
        if (allHold(transition.when, senses)) {
            next = transition.target;
            break;
        }
    }
    // Then the actions of the state the agent is now in.
    actions.clear();
    for (const Action& action : machine.states[static_cast<std::size_t>(next)].actions) actions.push_back(&action);
    return next;
}

int arbitrateLayers(const SubsumptionStack& stack, const CrowdSenses& senses) {
    // From the top: the first layer that fires suppresses every layer below it.
    for (std::size_t i = 0; i < stack.layers.size(); ++i)
        if (allHold(stack.layers[i].when, senses)) return static_cast<int>(i);
    return -1;
}

} // namespace stoa
