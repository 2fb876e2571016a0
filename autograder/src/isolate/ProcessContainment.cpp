#include "ProcessContainment.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>

#include <dirent.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

namespace stoa::grader {

namespace {

bool isNumber(const char* name) {
    if (*name == '\0') return false;
    for (const char* c = name; *c; ++c)
        if (*c < '0' || *c > '9') return false;
    return true;
}

// Calls `visit(pidText)` for every process in /proc.
template <typename Visit>
void forEachProcess(Visit&& visit) {
    DIR* proc = opendir("/proc");
    if (!proc) return;
    while (dirent* entry = readdir(proc))
        if (isNumber(entry->d_name)) visit(entry->d_name);
    closedir(proc);
}

// Reads a small /proc file into `buffer`; returns false when it is gone.
bool readSmallFile(const std::string& path, char* buffer, std::size_t size) {
    std::FILE* file = std::fopen(path.c_str(), "re");
    if (!file) return false;
    std::size_t count = std::fread(buffer, 1, size - 1, file);
    std::fclose(file);
    buffer[count] = '\0';
    return count > 0;
}

// Whether a child may unshare `flags`: a child tries and exits 0 on success.
bool childCanUnshare(int flags) {
    pid_t pid = fork();
    if (pid < 0) return false;
    if (pid == 0) _exit(unshare(flags) == 0 ? 0 : 1);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

} // namespace

std::size_t userTaskCount() {
    const uid_t me = getuid();
    std::size_t tasks = 0;
    char buffer[4096];
    forEachProcess([&](const char* pid) {
        if (!readSmallFile(std::string("/proc/") + pid + "/status", buffer, sizeof buffer)) return;
        const char* uid = std::strstr(buffer, "\nUid:");
        const char* threads = std::strstr(buffer, "\nThreads:");
        if (!uid || !threads) return;
        if (static_cast<uid_t>(std::strtoul(uid + 5, nullptr, 10)) != me) return;
        tasks += std::strtoul(threads + 9, nullptr, 10);
    });
    return tasks;
}

std::vector<ProcessEntry> processTable() {
    std::vector<ProcessEntry> table;
    char buffer[1024];
    forEachProcess([&](const char* pid) {
        if (!readSmallFile(std::string("/proc/") + pid + "/stat", buffer, sizeof buffer)) return;
        // "pid (comm) state ppid pgrp ...": comm may hold spaces and ')', so parse after the last ')'.
        const char* close = std::strrchr(buffer, ')');
        if (!close) return;
        char state = 0;
        long parent = 0;
        long pgrp = 0;
        unsigned long user = 0, system = 0;   // fields 14 and 15, in clock ticks
        const int read = std::sscanf(close + 1, " %c %ld %ld %*d %*d %*d %*u %*u %*u %*u %*u %lu %lu", &state, &parent,
                                     &pgrp, &user, &system);
        if (read < 3) return;
        ProcessEntry entry;
        entry.pid = static_cast<pid_t>(std::strtol(pid, nullptr, 10));
        entry.parent = static_cast<pid_t>(parent);
        entry.group = static_cast<pid_t>(pgrp);
        entry.ended = state == 'Z' || state == 'X' || state == 'x';
        static const double ticks = static_cast<double>(sysconf(_SC_CLK_TCK));
        if (read == 5 && ticks > 0) entry.cpuSeconds = static_cast<double>(user + system) / ticks;
        table.push_back(entry);
    });
    return table;
}

std::size_t processGroupSize(pid_t group) {
    std::size_t members = 0;
    for (const ProcessEntry& entry : processTable())
        if (entry.group == group && !entry.ended) ++members;
    return members;
}

double processGroupCpuSeconds(pid_t group) {
    double seconds = 0.0;
    for (const ProcessEntry& entry : processTable())
        if (entry.group == group && !entry.ended) seconds += entry.cpuSeconds;
    return seconds;
}

int usableCores() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        int count = CPU_COUNT(&set);
        if (count > 0) return count;
    }
    long online = sysconf(_SC_NPROCESSORS_ONLN);
    return online > 0 ? static_cast<int>(online) : 1;
}

int networkIsolationFlags() {
    static std::once_flag probed;
    static int flags = 0;
    std::call_once(probed, [] {
        if (childCanUnshare(CLONE_NEWUSER | CLONE_NEWNET)) flags = CLONE_NEWUSER | CLONE_NEWNET;
        else if (childCanUnshare(CLONE_NEWNET)) flags = CLONE_NEWNET;
    });
    return flags;
}

int pidNamespaceFlags() {
    static std::once_flag probed;
    static int flags = 0;
    std::call_once(probed, [] {
        // With a mount namespace where allowed: its process 1 mounts its own /proc.
        for (int candidate : {CLONE_NEWUSER | CLONE_NEWPID | CLONE_NEWNS, CLONE_NEWUSER | CLONE_NEWPID,
                              CLONE_NEWPID | CLONE_NEWNS, CLONE_NEWPID})
            if (childCanUnshare(candidate)) {
                flags = candidate;
                break;
            }
    });
    return flags;
}

int isolationFlags(bool network, bool pids) {
    int networkFlags = network ? networkIsolationFlags() : 0;
    int pidFlags = pids ? pidNamespaceFlags() : 0;
    if (pidFlags == 0 || (networkFlags | pidFlags) == pidFlags) return networkFlags | pidFlags;
    if (networkFlags == 0) return pidFlags;
    // Both, e.g. CLONE_NEWNET alone (root) with CLONE_NEWUSER | CLONE_NEWPID: try the union once.
    static std::mutex mutex;
    static std::map<int, bool> allowed;
    int both = networkFlags | pidFlags;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = allowed.find(both);
    if (found == allowed.end()) found = allowed.emplace(both, childCanUnshare(both)).first;
    return found->second ? both : networkFlags;
}

bool childrenHaveOwnUserNamespace() { return (networkIsolationFlags() & CLONE_NEWUSER) != 0; }

std::string networkIsolationNote() {
    if (networkIsolationFlags() != 0) return "";
    return "note: this system does not let the lab programs drop their network (unshare(CLONE_NEWNET) "
           "is not allowed); they run with the grader's network";
}

std::string printableText(const std::string& raw) {
    static const char kReplacement[] = "\xEF\xBF\xBD"; // U+FFFD
    std::string text;
    text.reserve(raw.size());
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(raw[i]); };
    for (std::size_t i = 0; i < raw.size();) {
        unsigned char c = byte(i);
        if (c < 0x80) {
            if (c == '\r') {
                text += '\n';
                i += (i + 1 < raw.size() && raw[i + 1] == '\n') ? 2 : 1;
                continue;
            }
            text += (c == '\n' || c == '\t' || (c >= 0x20 && c != 0x7f)) ? static_cast<char>(c) : '?';
            ++i;
            continue;
        }
        // A UTF-8 sequence: its length from the lead byte, then continuation bytes,
        // with overlong forms, surrogates and values past U+10FFFF refused.
        std::size_t length = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
        bool valid = length > 0 && i + length <= raw.size();
        for (std::size_t k = 1; valid && k < length; ++k) valid = (byte(i + k) & 0xC0) == 0x80;
        if (valid && length == 3) {
            unsigned char second = byte(i + 1);
            valid = !(c == 0xE0 && second < 0xA0) && !(c == 0xED && second >= 0xA0);
        }
        if (valid && length == 4) {
            unsigned char second = byte(i + 1);
            valid = !(c == 0xF0 && second < 0x90) && !(c == 0xF4 && second >= 0x90);
        }
        if (!valid) {
            text += kReplacement;
            ++i;
            continue;
        }
        text.append(raw, i, length);
        i += length;
    }
    return text;
}

} // namespace stoa::grader
