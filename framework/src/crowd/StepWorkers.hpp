#pragma once
// A few threads kept for the crowd's parallel step (CrowdSimulation::setThreads):
// run(job) has every thread, the caller's included, call job(thread) once and
// returns when all have. Made once per simulation, so that a step does not
// start threads. Private to framework/src/crowd.

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace stoa {

class StepWorkers {
public:
    /// `threads` >= 1 threads in all: the caller and threads - 1 started here.
    explicit StepWorkers(int threads);
    ~StepWorkers();
    StepWorkers(const StepWorkers&) = delete;
    StepWorkers& operator=(const StepWorkers&) = delete;

    int threads() const { return static_cast<int>(m_threads.size()) + 1; }
    /// Calls job(0) here and job(1) ... job(threads - 1) on the others, and
    /// waits for all; an exception a job throws is thrown again here.
    void run(const std::function<void(int)>& job);

private:
    void work(int thread);

    std::vector<std::thread> m_threads;
    std::mutex m_mutex;
    std::condition_variable m_start;
    std::condition_variable m_done;
    const std::function<void(int)>* m_job = nullptr;
    unsigned long m_round = 0;   // bumped by run(): a new job
    int m_pending = 0;           // threads still in this round's job
    bool m_quit = false;
    std::exception_ptr m_error;
};

} // namespace stoa
