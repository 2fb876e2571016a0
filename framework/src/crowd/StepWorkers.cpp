#include "StepWorkers.hpp"

namespace stoa {

StepWorkers::StepWorkers(int threads) {
    for (int t = 1; t < threads; ++t) m_threads.emplace_back([this, t] { work(t); });
}

StepWorkers::~StepWorkers() {
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_quit = true;
    }
    m_start.notify_all();
    for (std::thread& thread : m_threads) thread.join();
}

void StepWorkers::run(const std::function<void(int)>& job) {
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_job = &job;
        m_pending = static_cast<int>(m_threads.size());
        m_error = nullptr;
        ++m_round;
    }
    m_start.notify_all();
    std::exception_ptr error;
    try {
        job(0);
    } catch (...) {
        error = std::current_exception();
    }
    std::unique_lock<std::mutex> lock(m_mutex);
    m_done.wait(lock, [this] { return m_pending == 0; });
    m_job = nullptr;
    if (!error) error = m_error;
    if (error) std::rethrow_exception(error);
}

void StepWorkers::work(int thread) {
    unsigned long seen = 0;
    for (;;) {
        const std::function<void(int)>* job = nullptr;
        {
            std::unique_lock<std::mutex> lock(m_mutex);
            m_start.wait(lock, [&] { return m_quit || m_round != seen; });
            if (m_quit) return;
            seen = m_round;
            job = m_job;
        }
        std::exception_ptr error;
        try {
            (*job)(thread);
        } catch (...) {
            error = std::current_exception();
        }
        std::lock_guard<std::mutex> lock(m_mutex);
        if (error && !m_error) m_error = error;
        if (--m_pending == 0) m_done.notify_one();
    }
}

} // namespace stoa
