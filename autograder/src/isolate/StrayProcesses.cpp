#include "StrayProcesses.hpp"

#include "ProcessContainment.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <map>
#include <set>
#include <vector>

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace stoa::grader {

namespace {

// The registered children, for the interrupt handler as well: a fixed array of
// atomics, since a signal handler may not take a lock.
constexpr std::size_t kMaxRunning = 512;
std::atomic<pid_t> g_running[kMaxRunning];

bool isRegistered(pid_t pid) {
    for (const std::atomic<pid_t>& slot : g_running)
        if (slot.load() == pid) return true;
    return false;
}

// The strays in `table`: the members of `group` but its leader, and this
// process's unregistered children, then everything descended from those. A
// process in the group of another registered child is that child's to sweep:
// when a killed child dies before its namespace's process 1, this process
// adopts the init for a moment, and the blame is not another case's.
std::set<pid_t> straysIn(const std::vector<ProcessEntry>& table, pid_t group) {
    const pid_t self = getpid();
    std::set<pid_t> strays;
    std::multimap<pid_t, pid_t> children;
    for (const ProcessEntry& entry : table) {
        children.emplace(entry.parent, entry.pid);
        bool othersGroup = entry.group != group && isRegistered(entry.group);
        bool adopted = entry.parent == self && !isRegistered(entry.pid) && !othersGroup;
        bool inGroup = group > 0 && entry.group == group && entry.pid != group;
        if (adopted || inGroup) strays.insert(entry.pid);
    }
    std::vector<pid_t> toVisit(strays.begin(), strays.end());
    while (!toVisit.empty()) {
        pid_t parent = toVisit.back();
        toVisit.pop_back();
        auto [begin, end] = children.equal_range(parent);
        for (auto it = begin; it != end; ++it)
            if (strays.insert(it->second).second) toVisit.push_back(it->second);
    }
    return strays;
}

} // namespace

bool becomeSubreaper() {
    static const bool subreaper = prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0;
    return subreaper;
}

std::mutex& childStartMutex() {
    static std::mutex mutex;
    return mutex;
}

void registerChild(pid_t pid) {
    for (std::atomic<pid_t>& slot : g_running) {
        pid_t empty = 0;
        if (slot.compare_exchange_strong(empty, pid)) return;
    }
}

void unregisterChild(pid_t pid) {
    for (std::atomic<pid_t>& slot : g_running) {
        pid_t expected = pid;
        if (slot.compare_exchange_strong(expected, 0)) return;
    }
}

void killRegisteredChildren() {
    for (std::atomic<pid_t>& slot : g_running) {
        pid_t pid = slot.load();
        if (pid > 0) kill(-pid, SIGKILL);
    }
}

std::size_t killStrayProcesses(pid_t group) {
    // One sweep at a time: two would race to reap the same orphans.
    static std::mutex sweeping;
    std::lock_guard<std::mutex> lock(sweeping);
    const pid_t self = getpid();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    std::set<pid_t> killed;
    // A daemon that keeps forking makes new processes until the kill reaches it:
    // look again until a look finds nothing running. Killed processes cannot fork,
    // so this ends after as many rounds as the deepest chain of forks in flight.
    for (;;) {
        std::vector<ProcessEntry> table = processTable();
        std::set<pid_t> strays;
        {
            std::lock_guard<std::mutex> starting(childStartMutex());
            strays = straysIn(table, group);
        }
        bool busy = false;
        for (const ProcessEntry& entry : table) {
            if (strays.count(entry.pid) == 0) continue;
            if (!entry.ended) {
                kill(entry.pid, SIGKILL);
                killed.insert(entry.pid);
                busy = true;
            } else if (entry.parent == self) {
                waitpid(entry.pid, nullptr, WNOHANG);
                busy = true;
            }
        }
        if (!busy || std::chrono::steady_clock::now() > deadline) break;
        usleep(1000);
    }
    return killed.size();
}

} // namespace stoa::grader
