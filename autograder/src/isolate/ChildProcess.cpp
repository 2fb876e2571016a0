#include "ChildProcess.hpp"

#include "ChildSide.hpp"
#include "MountSandbox.hpp"
#include "ProcessContainment.hpp"
#include "StrayProcesses.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <mutex>
#include <cstring>
#include <sstream>

#include <fcntl.h>
#include <sched.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define STOA_GRADER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define STOA_GRADER_ASAN 1
#endif
#endif

namespace stoa::grader {

namespace {

using Clock = std::chrono::steady_clock;

extern "C" void killChildrenAndExit(int signal) {
    killRegisteredChildren();
    // End the way the signal would have ended us, so the shell sees it.
    struct sigaction defaultAction {};
    defaultAction.sa_handler = SIG_DFL;
    sigaction(signal, &defaultAction, nullptr);
    raise(signal);
}

// The grader's own argv in memory: from argv[0] (glibc's program_invocation_name)
// over as many bytes as /proc/self/cmdline holds. Read once.
std::size_t graderArgumentsLength() {
    static const std::size_t length = [] {
        std::FILE* file = std::fopen("/proc/self/cmdline", "re");
        if (!file) return std::size_t{0};
        std::size_t total = 0;
        char buffer[4096];
        for (std::size_t count; (count = std::fread(buffer, 1, sizeof buffer, file)) > 0;) total += count;
        std::fclose(file);
        return total;
    }();
    return length;
}

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string formatSeconds(double seconds) {
    std::ostringstream text;
    text << seconds;
    return text.str();
}

// Keeps the first quarter and the last three quarters of the limit: the head
// shows the first error, the tail the last one (where a stub's "not
// implemented" line is), and the count of what lies between is reported.
class OutputCapture {
public:
    explicit OutputCapture(std::size_t limit)
        : m_headLimit(limit / 4), m_tailLimit(limit - limit / 4) {}

    void append(const char* bytes, std::size_t count) {
        m_total += count;
        std::size_t toHead = std::min(count, m_headLimit - m_head.size());
        m_head.append(bytes, toHead);
        m_tail.append(bytes + toHead, count - toHead);
        if (m_tail.size() > 2 * m_tailLimit + 4096) m_tail.erase(0, m_tail.size() - m_tailLimit);
    }

    bool truncated() const { return m_total > m_headLimit + m_tailLimit; }

    std::string text() const {
        if (!truncated()) return m_head + m_tail;
        std::size_t dropped = m_total - m_headLimit - m_tailLimit;
        return m_head + "\n[... " + std::to_string(dropped) + " bytes of output left out ...]\n" +
               m_tail.substr(m_tail.size() - m_tailLimit);
    }

private:
    std::size_t m_headLimit;
    std::size_t m_tailLimit;
    std::string m_head;
    std::string m_tail;
    std::size_t m_total = 0;
};

// A pipe whose ends close themselves; both ends are close-on-exec, so a child
// started by another thread at the same moment does not inherit them.
class Pipe {
public:
    Pipe() {
        int ends[2];
        if (pipe2(ends, O_CLOEXEC) == 0) {
            m_read = ends[0];
            m_write = ends[1];
        }
    }
    ~Pipe() {
        closeRead();
        closeWrite();
    }
    Pipe(const Pipe&) = delete;
    Pipe& operator=(const Pipe&) = delete;

    bool valid() const { return m_read >= 0; }
    int readEnd() const { return m_read; }
    int writeEnd() const { return m_write; }
    void closeRead() {
        if (m_read >= 0) ::close(m_read);
        m_read = -1;
    }
    void closeWrite() {
        if (m_write >= 0) ::close(m_write);
        m_write = -1;
    }

private:
    int m_read = -1;
    int m_write = -1;
};

bool childHasEnded(pid_t pid) {
    siginfo_t info{};
    info.si_pid = 0;
    // WNOWAIT leaves the child a zombie, so its pid (and process group id)
    // cannot be reused before we kill what is left of the group.
    if (waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) != 0) return errno == ECHILD;
    return info.si_pid == pid;
}

void waitForEnd(pid_t pid) {
    siginfo_t info{};
    while (waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) != 0 && errno == EINTR) {
    }
}

int reap(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

// Reads what the pipe holds now; returns false at end of file.
bool drain(int fd, OutputCapture& capture) {
    char buffer[16384];
    for (;;) {
        ssize_t count = read(fd, buffer, sizeof buffer);
        if (count > 0) {
            capture.append(buffer, static_cast<std::size_t>(count));
            continue;
        }
        if (count == 0) return false;
        if (errno == EINTR) continue;
        return true; // EAGAIN: nothing more for now
    }
}

} // namespace

ProcessLimits defaultLimits(double timeoutSeconds) {
    ProcessLimits limits = withTimeout(ProcessLimits{}, timeoutSeconds);
    limits.environment.push_back("STOA_GL_CHECKED=1");
    if (builtWithAddressSanitizer()) limits.addressSpaceBytes = 0;
    return limits;
}

ProcessLimits withTimeout(ProcessLimits limits, double timeoutSeconds) {
    limits.timeoutSeconds = timeoutSeconds;
    limits.cpuSeconds = timeoutSeconds * usableCores() + 5.0;
    return limits;
}

bool builtWithAddressSanitizer() {
#ifdef STOA_GRADER_ASAN
    return true;
#else
    return false;
#endif
}

namespace {

// What watching a started child found.
struct Watch {
    bool timedOut = false;
    bool tooManyProcesses = false;
    bool reported = false;          // the namespace's process 1 sent `fromInit`
    bool reportOpen = false;        // its pipe was still open when the watch ended
    int fromInit[2] = {0, 0};       // the program's wait status, the processes it left
    double cpuSeconds = -1.0;       // at a timeout: the group's processor time
};

// The child's arguments, limits, environment, namespaces and file sandbox
// (`sandbox`, or `mounts` where Landlock is missing), all made before fork.
// Returns why the child cannot start, or "".
std::string prepareChild(const std::vector<std::string>& argv, const std::filesystem::path& workDir,
                         const ProcessLimits& limits, ChildSetup& setup, FileSandbox& sandbox, MountSandbox& mounts) {
    setup.arguments = argv;
    for (std::string& argument : setup.arguments) setup.argv.push_back(argument.data());
    setup.argv.push_back(nullptr);
    setup.workDir = workDir.string();
    if (limits.cpuSeconds > 0) setup.addLimit(RLIMIT_CPU, static_cast<rlim_t>(limits.cpuSeconds + 0.999));
    if (limits.addressSpaceBytes > 0) setup.addLimit(RLIMIT_AS, limits.addressSpaceBytes);
    if (limits.fileSizeBytes > 0) setup.addLimit(RLIMIT_FSIZE, limits.fileSizeBytes);
    setup.addLimit(RLIMIT_CORE, 0);
    setup.setEnvironment(limits.environment);
    setup.unshareFlags = isolationFlags(limits.isolateNetwork, limits.ownPidNamespace);
    sandbox = FileSandbox(limits.files);
    if (!sandbox.error().empty()) return "could not confine the files of " + argv[0] + ": " + sandbox.error();
    setup.fileSandbox = sandbox.descriptor();
    // Without Landlock, mounts stand in, in the child's own mount namespace only.
    const bool mountsInstead = limits.files.confine && !sandbox.valid() && (setup.unshareFlags & CLONE_NEWNS) != 0;
    mounts = MountSandbox(mountsInstead ? limits.files : FileAccess{});
    if (mounts.valid()) setup.mountSandbox = &mounts;
    setup.graderArguments = program_invocation_name;
    setup.graderArgumentsLength = program_invocation_name ? graderArgumentsLength() : 0;
    // RLIMIT_NPROC counts every task of the user; in the child's own user namespace
    // only the child's. It does not bind root: the watchdog is the guard there.
    if (limits.maxTasks > 0 && getuid() != 0) {
        bool ownCount = (setup.unshareFlags & CLONE_NEWUSER) != 0;
        setup.addLimit(RLIMIT_NPROC, static_cast<rlim_t>(limits.maxTasks + (ownCount ? 0 : userTaskCount())));
    }
    return "";
}

// Waits for the child under the limits while draining its output into
// `capture` (`pipeOpen` false once the pipe reached its end). With its own PID
// namespace (`ownPids`), its ending comes from the namespace's process 1
// through `reportFd`; `helpers` processes of its group are the grader's.
Watch watchChild(pid_t pid, int outputFd, int reportFd, bool ownPids, std::size_t helpers, const ProcessLimits& limits,
                 Clock::time_point start, OutputCapture& capture, bool& pipeOpen) {
    Watch watch;
    watch.reportOpen = ownPids;
    Clock::time_point lastCount = start;
    for (;;) {
        double remaining = limits.timeoutSeconds - secondsSince(start);
        if (remaining <= 0) {
            watch.timedOut = true;
            watch.cpuSeconds = processGroupCpuSeconds(pid);   // before the kill
            return watch;
        }
        // Wake at least every 25 ms to notice a child that exited while a
        // grandchild still holds the pipe open.
        int waitMs = static_cast<int>(std::min(remaining * 1000.0 + 1.0, 25.0));
        pollfd entries[2];
        nfds_t count = 0;
        if (pipeOpen) entries[count++] = {outputFd, POLLIN, 0};
        if (watch.reportOpen) entries[count++] = {reportFd, POLLIN, 0};
        poll(entries, count, waitMs);
        if (pipeOpen) pipeOpen = drain(outputFd, capture);
        if (watch.reportOpen) {
            ssize_t got = read(reportFd, watch.fromInit, sizeof watch.fromInit);
            watch.reported = got == static_cast<ssize_t>(sizeof watch.fromInit);
            if (got >= 0) watch.reportOpen = false;
            // The report is the init's last act: the child ends right after it.
            if (watch.reported) {
                waitForEnd(pid);
                return watch;
            }
        }
        if (childHasEnded(pid)) return watch;
        // The fork-bomb watchdog, ten times a second (it reads /proc).
        if (limits.maxProcesses > 0 && Clock::now() - lastCount >= std::chrono::milliseconds(100)) {
            lastCount = Clock::now();
            if (processGroupSize(pid) > limits.maxProcesses + helpers) {
                watch.tooManyProcesses = true;
                return watch;
            }
        }
    }
}

// Forks the child and waits for its exec: its pid, or -1 with `startError` set
// (the fork, the work folder, the sandbox or the exec failed; what it started is reaped).
pid_t startChild(const ChildSetup& setup, const std::vector<std::string>& argv, Pipe& output, Pipe& execStatus,
                 Pipe& report, std::string& startError) {
    pid_t pid = 0;
    {
        std::lock_guard<std::mutex> starting(childStartMutex());
        pid = fork();
        if (pid == 0) runChild(setup, output.writeEnd(), execStatus.writeEnd(), report.writeEnd());
        if (pid > 0) registerChild(pid);
    }
    if (pid < 0) {
        startError = std::string("could not fork: ") + std::strerror(errno);
        return -1;
    }
    setpgid(pid, pid); // also done by the child; whichever runs first wins the race
    output.closeWrite();
    execStatus.closeWrite();
    report.closeWrite();

    // The status pipe closes on a successful exec (close-on-exec) and carries
    // the failing step and errno otherwise.
    int failure[2] = {0, 0};
    ssize_t got;
    while ((got = read(execStatus.readEnd(), failure, sizeof failure)) < 0 && errno == EINTR) {
    }
    if (got != static_cast<ssize_t>(sizeof failure)) return pid;
    reap(pid);
    unregisterChild(pid);
    killStrayProcesses(pid);
    startError = failure[0] == 0
        ? "could not enter the work directory " + setup.workDir + ": " + std::strerror(failure[1])
        : failure[0] == 2 ? "could not confine the files of " + argv[0] + ": " + std::strerror(failure[1])
                          : "could not start " + argv[0] + ": " + std::strerror(failure[1]);
    return -1;
}

// How the program ended, from the watch and its wait status.
void describeEnding(ProcessOutcome& outcome, const Watch& watch, int status, std::size_t strays) {
    if (watch.timedOut) {
        outcome.ending = ProcessEnding::TimedOut;
        outcome.cpuSeconds = watch.cpuSeconds;
    } else if (watch.tooManyProcesses) {
        outcome.ending = ProcessEnding::TooManyProcesses;
    } else if (WIFSIGNALED(status)) {
        outcome.ending = ProcessEnding::Signalled;
        outcome.signal = WTERMSIG(status);
    } else {
        outcome.ending = ProcessEnding::Exited;
        outcome.exitCode = WEXITSTATUS(status);
    }
    // A program killed for its time or its processes has its group killed with it.
    if (!watch.timedOut && !watch.tooManyProcesses) outcome.strayProcesses = strays;
}

} // namespace

ProcessOutcome runProcess(const std::vector<std::string>& argv, const std::filesystem::path& workDir,
                          const ProcessLimits& limits) {
    ProcessOutcome outcome;
    outcome.timeoutSeconds = limits.timeoutSeconds;
    outcome.maxProcesses = limits.maxProcesses;
    if (argv.empty() || argv[0].empty()) {
        outcome.startError = "no program given";
        return outcome;
    }
    ChildSetup setup;
    FileSandbox sandbox;
    MountSandbox mounts;
    outcome.startError = prepareChild(argv, workDir, limits, setup, sandbox, mounts);
    if (!outcome.startError.empty()) return outcome;
    const bool ownPids = (setup.unshareFlags & CLONE_NEWPID) != 0;
    becomeSubreaper();

    Pipe output;
    Pipe execStatus;
    Pipe report;   // from the namespace's process 1: the program's wait status, and what it left
    if (!output.valid() || !execStatus.valid() || !report.valid()) {
        outcome.startError = std::string("could not create a pipe: ") + std::strerror(errno);
        return outcome;
    }

    Clock::time_point start = Clock::now();
    const pid_t pid = startChild(setup, argv, output, execStatus, report, outcome.startError);
    if (pid < 0) {
        outcome.seconds = secondsSince(start);
        return outcome;
    }

    fcntl(output.readEnd(), F_SETFL, fcntl(output.readEnd(), F_GETFL) | O_NONBLOCK);
    fcntl(report.readEnd(), F_SETFL, fcntl(report.readEnd(), F_GETFL) | O_NONBLOCK);
    OutputCapture capture(limits.outputLimitBytes);
    bool pipeOpen = true;
    // The child and its namespace's process 1 are in the group beside the program.
    Watch watch = watchChild(pid, output.readEnd(), report.readEnd(), ownPids, ownPids ? 2 : 0, limits, start,
                             capture, pipeOpen);

    // Whatever is left (the child if it timed out; grandchildren of its group,
    // daemons that left the group, in any case) goes now, before the child is
    // reaped: a zombie's pid, and so its group's id, cannot be reused meanwhile.
    // Then the last output is read.
    if (watch.timedOut || watch.tooManyProcesses) {
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
    }
    // A namespace's process 1 that reported has killed everything the program
    // started: nothing can leave a PID namespace. The sweep, which reads /proc,
    // is then skipped (it would delay the end of every case a little).
    std::size_t strays = watch.reported ? 0 : killStrayProcesses(pid);
    int status = reap(pid);
    unregisterChild(pid);
    if (pipeOpen) drain(output.readEnd(), capture);
    if (!watch.reported && watch.reportOpen)
        watch.reported = read(report.readEnd(), watch.fromInit, sizeof watch.fromInit) ==
                         static_cast<ssize_t>(sizeof watch.fromInit);
    if (watch.reported) {
        status = watch.fromInit[0];
        strays += static_cast<std::size_t>(watch.fromInit[1]);
    }

    outcome.seconds = secondsSince(start);
    outcome.output = printableText(capture.text());
    outcome.outputTruncated = capture.truncated();
    describeEnding(outcome, watch, status, strays);
    return outcome;
}

void killChildrenOnInterrupt() {
    struct sigaction action {};
    action.sa_handler = killChildrenAndExit;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

std::string ProcessOutcome::describe() const {
    switch (ending) {
    case ProcessEnding::Exited:
        return "exited with status " + std::to_string(exitCode);
    case ProcessEnding::Signalled:
        if (signal == SIGKILL || signal == SIGXCPU || signal == SIGXFSZ || signal == SIGTERM)
            return "was killed by " + describeSignal(signal);
        return "crashed with " + describeSignal(signal);
    case ProcessEnding::TimedOut:
        return "timed out after " + formatSeconds(timeoutSeconds) + " s";
    case ProcessEnding::TooManyProcesses:
        return "started more than " + std::to_string(maxProcesses) + " processes (a fork bomb?) and was stopped";
    case ProcessEnding::FailedToStart:
        return startError;
    }
    return "ended in an unknown way";
}

std::string ProcessOutcome::lastOutputLine() const {
    std::size_t end = output.find_last_not_of(" \t\r\n");
    if (end == std::string::npos) return "";
    std::size_t begin = output.rfind('\n', end);
    begin = begin == std::string::npos ? 0 : begin + 1;
    return output.substr(begin, end + 1 - begin);
}

std::string describeSignal(int signal) {
    struct Known {
        int number;
        const char* name;
        const char* meaning;
    };
    static const Known known[] = {
        {SIGSEGV, "SIGSEGV", "segmentation fault: a bad pointer or an index out of range"},
        {SIGBUS, "SIGBUS", "bus error: a bad pointer"},
        {SIGFPE, "SIGFPE", "arithmetic error, e.g. integer division by zero"},
        {SIGILL, "SIGILL", "illegal instruction"},
        {SIGABRT, "SIGABRT", "abort: a failed assertion or an uncaught exception"},
        {SIGKILL, "SIGKILL", "killed, e.g. out of memory"},
        {SIGTERM, "SIGTERM", "terminated"},
        {SIGXCPU, "SIGXCPU", "CPU time limit exceeded"},
        {SIGXFSZ, "SIGXFSZ", "file size limit exceeded"},
        {SIGPIPE, "SIGPIPE", "wrote to a closed pipe"},
        {SIGTRAP, "SIGTRAP", "trap"},
        {SIGSYS, "SIGSYS", "bad system call"},
        {SIGHUP, "SIGHUP", "hang-up"},
        {SIGINT, "SIGINT", "interrupted"},
        {SIGQUIT, "SIGQUIT", "quit"},
    };
    for (const Known& entry : known)
        if (entry.number == signal) return std::string(entry.name) + " (" + entry.meaning + ")";
    return "signal " + std::to_string(signal);
}

} // namespace stoa::grader
