// Lab 10, part 1: how an agent decides. Read docs/labs/10_crowds.md, "Finite
// state machines" and "Subsumption", first. The simulation calls one of the two
// for every agent at every step, with its senses of that step
// (lab10.hpp declares both and says what they return).

#include "lab10.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/crowd/CrowdLab.hpp>

namespace stoa {

int stepStateMachine(const StateMachine& machine, int current, const CrowdSenses& senses,
                     std::vector<const Action*>& actions) {
    // TODO(lab10): try the transitions of machine.states[current] in their
    // order; a transition fires when senses.holds() is true for every condition
    // in its `when` list. The first that fires moves the agent to its target;
    // none: it stays. Then fill `actions` with the actions of the state it is
    // in now, and return that state (docs: "Finite state machines").
    (void)machine;
    (void)current;
    (void)senses;
    (void)actions;
    throw NotImplemented("stepStateMachine()");
}

int arbitrateLayers(const SubsumptionStack& stack, const CrowdSenses& senses) {
    // TODO(lab10): the layers are listed from the highest priority down.
    // Return the index of the first whose conditions all hold (no conditions:
    // it always fires), or -1 when none does (docs: "Subsumption").
    (void)stack;
    (void)senses;
    throw NotImplemented("arbitrateLayers()");
}

} // namespace stoa
