#pragma once
// What the grader can learn about, and do to, the processes a lab program
// starts: how many tasks this user runs (for RLIMIT_NPROC), how many processes
// are in a child's process group (the fork-bomb watchdog), the process table
// (for the processes a lab program leaves behind, StrayProcesses.hpp), which
// namespaces this system lets a child enter, and how a child's raw output is
// made safe to print in a report.

#include <cstddef>
#include <string>
#include <vector>

#include <sys/types.h>

namespace stoa::grader {

/// The number of tasks (threads included) whose real user is this process's:
/// what the kernel compares with RLIMIT_NPROC outside a user namespace. Reads /proc.
std::size_t userTaskCount();

/// The number of processes whose process group is `group`. Reads /proc.
std::size_t processGroupSize(pid_t group);

/// The processor time the live processes of process group `group` have used
/// (user and system, all their threads): how busy a program was when it was
/// stopped. A program waiting on something uses next to none.
double processGroupCpuSeconds(pid_t group);

/// One line of the process table, as /proc/<pid>/stat tells it.
struct ProcessEntry {
    pid_t pid = 0;
    pid_t parent = 0;
    pid_t group = 0;
    bool ended = false;    // a zombie (or dead): it runs no more, but has not been reaped
    double cpuSeconds = 0.0;   // processor time it has used, user and system
};

/// Every process this one can see in /proc (threads are not processes).
std::vector<ProcessEntry> processTable();

/// The number of CPUs this process may run on (at least 1).
int usableCores();

/// The unshare() flags a child can use to lose its network on this system:
/// CLONE_NEWUSER | CLONE_NEWNET where user namespaces are allowed, CLONE_NEWNET
/// alone where only that is (root without user namespaces), 0 where neither.
/// Probed once, by a short-lived child, on the first call.
int networkIsolationFlags();

/// The unshare() flags a child can use to get its own PID namespace, in which
/// nothing it starts can outlive it (the namespace's first process ending kills
/// the rest): CLONE_NEWUSER | CLONE_NEWPID where user namespaces are allowed,
/// CLONE_NEWPID alone for root without them, 0 where neither; with CLONE_NEWNS
/// where a mount namespace is allowed too (for a /proc of its own). Probed once.
int pidNamespaceFlags();

/// The flags a child unshares for `network` and `pids` together: their union
/// where the system allows it (probed once per combination), else the network
/// flags alone, so that a PID namespace never costs the network isolation.
int isolationFlags(bool network, bool pids);

/// True when the children run in their own user namespace, where RLIMIT_NPROC
/// counts only their own tasks.
bool childrenHaveOwnUserNamespace();

/// One line for a note when networkIsolationFlags() is 0, else "".
std::string networkIsolationNote();

/// `raw` as printable UTF-8: tabs and newlines stay, "\r\n" and a lone '\r'
/// become '\n', other control characters become '?', and bytes that are not
/// valid UTF-8 (binary output, a sequence cut by truncation) become U+FFFD.
std::string printableText(const std::string& raw);

} // namespace stoa::grader
