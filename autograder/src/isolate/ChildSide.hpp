#pragma once
// The child's side of runProcess() (ChildProcess.hpp): what it needs, prepared
// before fork, and what it does between fork and exec. Only async-signal-safe
// calls run after fork: the grader has other threads, one of which may hold
// malloc's lock at that moment.

#include "MountSandbox.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

extern char** environ;

namespace stoa::grader {

// Everything the child needs, prepared before fork: after fork only
// async-signal-safe calls are allowed (another thread may hold malloc's lock).
struct ChildSetup {
    std::vector<std::string> arguments;
    std::vector<char*> argv;
    std::vector<std::string> environment;
    std::vector<char*> envp;
    std::string workDir;
    int unshareFlags = 0;
    int fileSandbox = -1;   // a Landlock ruleset (FileSandbox.hpp) entered right before exec; -1: none
    const MountSandbox* mountSandbox = nullptr;   // or, without Landlock, mounts made before exec (CLONE_NEWNS only)
    // The grader's own command line in memory (argv[0] on, its length): a PID
    // namespace's process 1 is a copy of the grader and blanks it, so that the
    // program cannot read the grader's paths from /proc/1/cmdline.
    char* graderArguments = nullptr;
    std::size_t graderArgumentsLength = 0;
    int descriptorLimit = static_cast<int>(std::min<long>(sysconf(_SC_OPEN_MAX), 1 << 16));
    // In a new user namespace the child maps the grader's own uid and gid onto
    // themselves (the lines for /proc/self/uid_map and gid_map, made before the
    // fork). Unmapped, it would run as "nobody", and Mesa, unable to use the
    // user's shader cache, would compile every shader again: 3-4x slower renders.
    std::string uidMap = std::to_string(getuid()) + " " + std::to_string(getuid()) + " 1\n";
    std::string gidMap = std::to_string(getgid()) + " " + std::to_string(getgid()) + " 1\n";
    struct Limit {
        int resource;
        rlimit value;
    };
    std::vector<Limit> limits;

    void addLimit(int resource, rlim_t wanted) {
        rlimit current{};
        if (getrlimit(resource, &current) != 0) return;
        rlim_t soft = wanted;
        if (current.rlim_max != RLIM_INFINITY && soft > current.rlim_max) soft = current.rlim_max;
        limits.push_back({resource, rlimit{soft, current.rlim_max}});
    }

    // The grader's environment with `overrides` ("NAME=value") replacing or adding entries.
    void setEnvironment(const std::vector<std::string>& overrides) {
        auto nameOf = [](const std::string& entry) { return entry.substr(0, entry.find('=')); };
        for (char** entry = environ; entry && *entry; ++entry) {
            std::string text = *entry;
            bool replaced = std::any_of(overrides.begin(), overrides.end(),
                                        [&](const std::string& o) { return nameOf(o) == nameOf(text); });
            if (!replaced) environment.push_back(text);
        }
        environment.insert(environment.end(), overrides.begin(), overrides.end());
        for (std::string& entry : environment) envp.push_back(entry.data());
        envp.push_back(nullptr);
    }
};

/// The child, from fork on: its own process group, stdin from /dev/null, stdout
/// and stderr to `outputFd`, every other descriptor close-on-exec, the
/// namespaces of `setup.unshareFlags`, then the program. With CLONE_NEWPID it
/// starts the namespace's process 1, which starts the program and writes its
/// wait status and the count of processes it left to `reportFd`. A failure to
/// start goes to `errorFd` as {step (0: chdir, 1: exec or fork, 2: the file
/// sandbox), errno}. With CLONE_NEWNS as well, process 1 mounts a /proc of its
/// own namespace: the program sees only its own processes there.
[[noreturn]] void runChild(const ChildSetup& setup, int outputFd, int errorFd, int reportFd);

} // namespace stoa::grader
