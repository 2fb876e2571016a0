#pragma once
// Simulated time in fixed steps. A window feeds it the wall time that passed;
// it answers how many steps of `step()` seconds to simulate, so what moves on
// screen never depends on the frame rate, and a graded render (which feeds it
// no wall time) is the same on every machine.

namespace stoa {

class FixedStepClock {
public:
    /// step > 0 seconds; at most maxStepsPerAdvance steps are returned at once, so a
    /// stalled frame (a breakpoint, a slow machine) does not snowball.
    explicit FixedStepClock(double step = 1.0 / 60.0, int maxStepsPerAdvance = 8);

    /// Adds `realSeconds` (>= 0) and returns how many whole steps are now due.
    int advance(double realSeconds);

    double step() const { return m_step; }
    /// Seconds simulated so far: steps taken * step().
    double simulatedSeconds() const { return static_cast<double>(m_steps) * m_step; }
    long long steps() const { return m_steps; }

private:
    double m_step;
    int m_maxSteps;
    double m_accumulated = 0.0;
    long long m_steps = 0;
};

} // namespace stoa
