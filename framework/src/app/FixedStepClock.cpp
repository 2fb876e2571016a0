#include <stoa/app/FixedStepClock.hpp>
#include <stoa/core/Assert.hpp>

namespace stoa {

FixedStepClock::FixedStepClock(double step, int maxStepsPerAdvance) : m_step(step), m_maxSteps(maxStepsPerAdvance) {
    STOA_ASSERT(step > 0.0, "FixedStepClock::FixedStepClock(): the step must be a positive number of seconds");
    STOA_ASSERT(maxStepsPerAdvance > 0, "FixedStepClock::FixedStepClock(): allow at least one step per advance");
}

int FixedStepClock::advance(double realSeconds) {
    STOA_ASSERT(realSeconds >= 0.0, "FixedStepClock::advance(): time only moves forward; pass the seconds elapsed");
    m_accumulated += realSeconds;
    int due = static_cast<int>(m_accumulated / m_step);
    if (due > m_maxSteps) {
        // Drop the backlog rather than trying to catch up.
        due = m_maxSteps;
        m_accumulated = 0.0;
    } else {
        m_accumulated -= due * m_step;
    }
    m_steps += due;
    return due;
}

} // namespace stoa
