// The parallel step: the same crowd as the serial step, bit for bit.
//
// The serial step visits the living in the grid's order, and each agent sees
// the others as the agents before it in that order left them: dead if one
// attacked it, moved if it seeks or flees one that has moved. Everything else
// an agent reads (the grid of where all stood when the step began, its own
// state, the maps, the random numbers of (agent, step)) no agent changes
// during a step. So:
//   1. every thread steps agents ahead of their turn, in place (keeping a copy
//      of each as it was), reading the others as they stood when the step
//      began, and records what each did to the others (the agent it
//      attacked, the messages it sent) and the positions of others it read;
//   2. the caller then goes through the agents in the serial order: an agent
//      attacked earlier in the step is put back as it was and passed over (as
//      in the serial step); one that read a position that has changed since,
//      or stood within reach of an agent attacked earlier in this step (its
//      senses might have seen that one alive), or whose pass could not record
//      what it did, is put back and stepped again there, exactly as the serial
//      step does; every other agent keeps its step, and its attack and
//      messages are applied.
// An agent stepped ahead and the serial step read the same values, so they
// compute the same bits. Worlds with samples or crumbs step serially: every pick-up
// and drop changes a list all agents read.

#include <stoa/crowd/CrowdSimulation.hpp>

#include "CrowdMath.hpp"
#include "CrowdStepState.hpp"
#include "StepWorkers.hpp"

#include <algorithm>
#include <cstring>
#include <exception>
#include <thread>

namespace stoa {

using namespace crowdmath;

namespace {

constexpr std::size_t kBlock = 128;   // agents a thread takes at a time in the first pass

bool sameBits(glm::vec2 a, glm::vec2 b) { return std::memcmp(&a, &b, sizeof a) == 0; }

} // namespace

void CrowdSimulation::setThreads(int threads, int fromAgents) {
    m_parallelFrom = static_cast<std::size_t>(std::max(0, fromAgents));
    threads = std::max(1, threads);
    if (threads == this->threads()) return;
    m_workers.reset();
    m_threadScratch.clear();
    if (threads > 1) {
        m_workers = std::make_unique<StepWorkers>(threads);
        m_threadScratch.resize(static_cast<std::size_t>(threads));
    }
}

int CrowdSimulation::threads() const { return m_workers ? m_workers->threads() : 1; }

void CrowdSimulation::speculate(int thread, std::atomic<std::size_t>& next) {
    StepScratch& scratch = m_threadScratch[static_cast<std::size_t>(thread)];
    scratch.heard.clear();
    const std::size_t count = m_cellAgents.size();
    for (;;) {
        const std::size_t begin = next.fetch_add(kBlock);
        if (begin >= count) return;
        const std::size_t end = std::min(count, begin + kBlock);
        for (std::size_t k = begin; k < end; ++k) {
            if (k + 2 * kPrefetchAhead < end) prefetchPlace(k);
            const std::size_t i = static_cast<std::size_t>(m_cellAgents[k].agent);
            Outcome& outcome = m_outcomes[k];
            outcome.before = m_agents[i];
            outcome.victim = -1;
            outcome.targetCount = 0;
            outcome.thread = thread;
            outcome.heardBegin = scratch.heard.size();
            outcome.blocked = 0;
            outcome.redo = false;
            scratch.outcome = &outcome;
            try {
                stepAgent(i, m_agents[i], scratch);
            } catch (const std::exception&) {
                outcome.redo = true;   // thrown again in its turn, by the serial step
            }
            outcome.heardEnd = scratch.heard.size();
        }
    }
}

bool CrowdSimulation::outcomeHolds(std::size_t index, const Outcome& outcome) const {
    if (outcome.redo) return false;
    // The positions it read as the step began: still so in its turn?
    for (int t = 0; t < outcome.targetCount; ++t) {
        const auto other = static_cast<std::size_t>(outcome.targets[t]);
        if (m_places[other] < static_cast<int>(m_place) && !sameBits(m_agents[other].position, outcome.targetPositions[t]))
            return false;
    }
    // A victim earlier in this step within reach: its senses may have seen it alive.
    const float reach = m_queryReach * 1.001f + 0.01f;
    const glm::vec2 from = startPosition(index);
    for (const glm::vec2 victim : m_stepKills)
        if (distanceSquared(victim, from) <= reach * reach) return false;
    return true;
}

void CrowdSimulation::undoSpeculation(std::size_t index) {
    CrowdAgent& agent = m_agents[index];
    const std::uint32_t heard = agent.nextMessages;   // sent to it earlier in this step
    agent = m_outcomes[static_cast<std::size_t>(m_places[index])].before;
    agent.nextMessages = heard;
}

void CrowdSimulation::commit(const Outcome& outcome) {
    const StepScratch& scratch = m_threadScratch[static_cast<std::size_t>(outcome.thread)];
    for (std::size_t h = outcome.heardBegin; h < outcome.heardEnd; ++h)
        m_agents[static_cast<std::size_t>(scratch.heard[h].first)].nextMessages |= scratch.heard[h].second;
    if (outcome.victim >= 0) kill(static_cast<std::size_t>(outcome.victim));
    m_blockedMoves += outcome.blocked;
}

void CrowdSimulation::stepParallel() {
    stepTheDead();
    m_outcomes.resize(m_cellAgents.size());
    std::atomic<std::size_t> next{0};
    m_workers->run([&](int thread) { speculate(thread, next); });
    for (StepScratch& scratch : m_threadScratch) scratch.outcome = nullptr;
    m_committing = true;
    for (std::size_t k = 0; k < m_cellAgents.size(); ++k) {
        const std::size_t i = static_cast<std::size_t>(m_cellAgents[k].agent);
        if (!m_living[i]) continue;   // attacked earlier in this step (and undone then)
        m_place = k;
        if (outcomeHolds(i, m_outcomes[k])) {
            commit(m_outcomes[k]);
        } else {
            undoSpeculation(i);
            stepAgent(i, m_agents[i], *m_serialScratch);
        }
    }
    m_committing = false;
    endStep();
}

} // namespace stoa
