#pragma once
// What one agent's step writes besides the agent itself, in the serial step
// and in the parallel step's first pass (CrowdSimulation's private parts;
// framework/src/crowd only).

#include <stoa/crowd/CrowdSimulation.hpp>

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace stoa {

/// One agent stepped ahead of its turn (in place) and what it did to the
/// others, kept in its turn if what it read then is still so.
struct CrowdSimulation::Outcome {
    static constexpr int kMaxReads = 2;

    CrowdAgent before;                   // the agent as the step began: to step it again, or to undo it
    int victim = -1;                     // the agent it attacked, if any
    int targets[kMaxReads] = {};         // agents whose position it read (seek, flee) ...
    glm::vec2 targetPositions[kMaxReads] = {};   // ... and what it read
    int targetCount = 0;
    int thread = 0;                      // whose scratch holds its messages
    std::size_t heardBegin = 0, heardEnd = 0;   // its messages: [begin, end) of that scratch's heard
    int blocked = 0;                     // moves the collision map turned aside
    bool redo = false;                   // step it again in its turn (it read too much, or threw)
};

/// Per thread: the actions list the lab's behaviour fills, and where the
/// parallel pass records what an agent did to others (outcome null: the serial step).
struct CrowdSimulation::StepScratch {
    static constexpr int kMemo = 4;
    static constexpr int kDrawn = 4;

    std::vector<const Action*> actions;
    std::uint32_t randomBase = 0;   // randomBase() of the agent stepping, set as its step begins
    float drawn[kDrawn] = {};       // its behaviour's first kDrawn numbers (Condition::index, Action::index)
    // direction() of the headings the agent stepping has had this step (its
    // last step's first): only a memo, so any entry of the same bits is right.
    float memoHeadings[kMemo] = {};
    glm::vec2 memoDirections[kMemo] = {};
    int memoCount = 0;
    int memoNext = 0;
    Outcome* outcome = nullptr;
    std::vector<std::pair<int, std::uint32_t>> heard;   // (hearer, message bit), in the order sent
};

} // namespace stoa
