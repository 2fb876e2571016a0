#pragma once
// Processes that outlive the program that started them. A lab program can fork,
// call setsid() and fork again: the daemon leaves the program's process group and
// its parent, and could rewrite results.json after the grader has written it.
//
// Two guards, the second where the first is missing:
//   - each child runs in its own PID namespace where the system allows one
//     (ChildProcess.cpp); when the program ends, the namespace's first process
//     kills everything else in it and says how many were still running;
//   - the grader is a child subreaper (prctl PR_SET_CHILD_SUBREAPER, Linux >= 3.4):
//     an orphan becomes its child instead of init's, and killStrayProcesses()
//     kills every such process (and its descendants) after each program, and
//     once more before any report is written.
//
// runProcess() registers the children it waits for; every other process this
// one has adopted is a stray.

#include <cstddef>
#include <mutex>

#include <sys/types.h>

namespace stoa::grader {

/// Makes this process a child subreaper, once; later calls return the first
/// answer. False where the kernel refuses (before Linux 3.4): strays then go to
/// init, and only the PID namespaces and the process groups contain them.
bool becomeSubreaper();

/// Held while a child is forked and registered, so that a sweep in another
/// thread does not take the new child for a stray.
std::mutex& childStartMutex();

/// The children runProcess() waits for; a sweep leaves them alone.
void registerChild(pid_t pid);
void unregisterChild(pid_t pid);

/// SIGKILL to the process group of every registered child. Async-signal-safe
/// (for the interrupt handler): no lock, no allocation.
void killRegisteredChildren();

/// Kills, until none is left, every process of process group `group` (0: no
/// group) but its leader, and every process this one adopted and did not
/// register, with all their descendants; reaps the ones that become its
/// children. Returns how many were running. Gives up after a few seconds
/// (a process that cannot be killed, e.g. stuck in the kernel).
std::size_t killStrayProcesses(pid_t group = 0);

} // namespace stoa::grader
