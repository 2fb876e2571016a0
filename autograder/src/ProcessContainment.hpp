#pragma once
// What the grader can learn about, and do to, the processes a lab program
// starts: how many tasks this user runs (for RLIMIT_NPROC), how many processes
// are in a child's process group (the fork-bomb watchdog), whether this system
// lets a child drop its network, and how a child's raw output is made safe to
// print in a report.

#include <cstddef>
#include <string>

#include <sys/types.h>

namespace stoa::grader {

/// The number of tasks (threads included) whose real user is this process's:
/// what the kernel compares with RLIMIT_NPROC outside a user namespace. Reads /proc.
std::size_t userTaskCount();

/// The number of processes whose process group is `group`. Reads /proc.
std::size_t processGroupSize(pid_t group);

/// The number of CPUs this process may run on (at least 1).
int usableCores();

/// The unshare() flags a child can use to lose its network on this system:
/// CLONE_NEWUSER | CLONE_NEWNET where user namespaces are allowed, CLONE_NEWNET
/// alone where only that is (root without user namespaces), 0 where neither.
/// Probed once, by a short-lived child, on the first call.
int networkIsolationFlags();

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
