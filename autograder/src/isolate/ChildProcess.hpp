#pragma once
// Runs one program as a child process under limits, the way the grader runs a
// student's lab: fork + exec (no shell), stdout and stderr merged into one pipe
// and kept to a few kilobytes, a wall-clock timeout after which the child's
// whole process group is killed, and resource limits set in the child before
// exec. The call always returns; nothing the child does can hang the grader.
//
// Containment, where the system allows it (ProcessContainment.hpp):
//   - nothing outlives the program: it runs as process 2 of its own PID
//     namespace, whose process 1 kills what is left when the program ends; the
//     grader is a child subreaper and kills the processes it adopts after each
//     program (StrayProcesses.hpp); the outcome counts them (strayProcesses);
//   - no network: the child unshares a user and a network namespace before exec;
//   - its files: with `files` confined, the program may read only those trees and
//     write only its own folder (Landlock, FileSandbox.hpp), and sees a /proc of
//     its own PID namespace, without the grader's processes;
//   - a process count: RLIMIT_NPROC (this user's tasks now + a margin, or the
//     margin alone inside the child's own user namespace), and a watchdog that
//     kills the group once it holds more than `maxProcesses` processes (the only
//     guard when the grader runs as root, whom RLIMIT_NPROC does not bind);
//   - output made printable: binary bytes and control characters are replaced.

#include "FileSandbox.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace stoa::grader {

/// Limits for one child. Zero means "no limit" for every field but the timeout.
struct ProcessLimits {
    double timeoutSeconds = 60.0;                         // wall clock; then SIGKILL to the process group
    double cpuSeconds = 65.0;                             // RLIMIT_CPU (the grader uses timeout + 5 s)
    std::uint64_t addressSpaceBytes = 4ull << 30;         // RLIMIT_AS, 4 GiB
    std::uint64_t fileSizeBytes = 64ull << 20;            // RLIMIT_FSIZE, 64 MiB per file
    std::size_t outputLimitBytes = 4096;                  // captured output kept (head and tail)
    std::size_t maxProcesses = 32;                        // processes in the child's group, the child included
    std::size_t maxTasks = 256;                           // RLIMIT_NPROC margin: threads count (llvmpipe's ~cores)
    bool isolateNetwork = true;                           // unshare the network where the OS allows it
    bool ownPidNamespace = true;                          // a PID namespace where the OS allows it
    std::vector<std::string> environment;                 // "NAME=value" set in the child's environment
    FileAccess files;                                     // what it may read and write; unconfined by default
};

/// The limits the grader uses for a given timeout: CPU time timeout x cores + 5 s
/// (llvmpipe renders on one thread per core), STOA_GL_CHECKED=1 so that a GL error
/// ends the lab program with a message naming the call, and no
/// address-space limit when this program was built with AddressSanitizer (its
/// shadow memory needs terabytes of address space; the lab programs share the build).
ProcessLimits defaultLimits(double timeoutSeconds);

/// `limits` with another timeout, and the CPU limit that goes with it as in defaultLimits().
ProcessLimits withTimeout(ProcessLimits limits, double timeoutSeconds);

/// True when this program (and so the lab programs of its build) was built with
/// AddressSanitizer, which makes code several times slower.
bool builtWithAddressSanitizer();

enum class ProcessEnding {
    Exited,          // returned from main or called exit(); see exitCode
    Signalled,       // killed by a signal it did not handle; see signal
    TimedOut,        // ran past timeoutSeconds and was killed
    TooManyProcesses,// its group grew past maxProcesses (a fork bomb) and was killed
    FailedToStart,   // fork or exec failed; see startError
};

struct ProcessOutcome {
    ProcessEnding ending = ProcessEnding::FailedToStart;
    int exitCode = -1;             // valid when ending == Exited
    int signal = 0;                // valid when ending == Signalled
    double seconds = 0.0;          // wall-clock run time
    double timeoutSeconds = 0.0;   // the limit it ran under, for describe()
    std::string output;            // stdout and stderr interleaved, possibly truncated, printable UTF-8
    std::size_t maxProcesses = 0;  // the limit it ran under, for describe()
    bool outputTruncated = false;  // true when `output` left bytes out (a marker line says how many)
    std::string startError;        // why it did not start (FailedToStart only)
    std::size_t strayProcesses = 0;// processes it left running when it ended (all killed); 0 after a timeout
    double cpuSeconds = -1.0;      // TimedOut: the processor time its processes had used when stopped; -1 unknown

    /// Timed out while computing (processor time at least a quarter of the
    /// wall time): too slow, or a loop without end; not waiting on anything.
    bool busyWhenStopped() const { return ending == ProcessEnding::TimedOut && cpuSeconds >= 0.25 * seconds; }

    bool exitedWith(int code) const { return ending == ProcessEnding::Exited && exitCode == code; }
    /// One line: "exited with status 1", "crashed with SIGSEGV (segmentation fault)",
    /// "timed out after 60 s", "could not start /x/y: No such file or directory",
    /// "started more than 32 processes (a fork bomb?) and was stopped".
    std::string describe() const;
    /// The last non-empty line of `output` ("" when there is none).
    std::string lastOutputLine() const;
};

/// Runs `argv` (argv[0] is the program's path; no PATH search, no shell) in
/// `workDir` (the current directory when empty) and waits for it under `limits`.
/// The child gets its own process group; when it ends or times out, whatever is
/// left of that group (grandchildren holding the pipe open), and every process it
/// started that left the group (a setsid() daemon), is killed too.
/// Safe to call from several threads at once.
ProcessOutcome runProcess(const std::vector<std::string>& argv, const std::filesystem::path& workDir,
                          const ProcessLimits& limits);

/// Makes Ctrl-C (SIGINT) and SIGTERM kill the process groups of the children
/// running at that moment before the grader itself ends; without it they would
/// go on rendering, since each runs in its own process group. Call once from main().
void killChildrenOnInterrupt();

/// "SIGSEGV (segmentation fault)" for a signal number; "signal 77" for an unknown one.
std::string describeSignal(int signal);

} // namespace stoa::grader
