#include "ChildProcess.hpp"

#include "ProcessContainment.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <sstream>

#include <fcntl.h>
#include <sched.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/syscall.h>
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

extern char** environ;

namespace stoa::grader {

namespace {

using Clock = std::chrono::steady_clock;

// The process groups of the running children, for the interrupt handler: a
// fixed array of atomics, since a signal handler may not take a lock.
constexpr std::size_t kMaxRunning = 512;
std::atomic<pid_t> g_running[kMaxRunning];

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

extern "C" void killChildrenAndExit(int signal) {
    for (std::atomic<pid_t>& slot : g_running) {
        pid_t pid = slot.load();
        if (pid > 0) kill(-pid, SIGKILL);
    }
    // End the way the signal would have ended us, so the shell sees it.
    struct sigaction defaultAction {};
    defaultAction.sa_handler = SIG_DFL;
    sigaction(signal, &defaultAction, nullptr);
    raise(signal);
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

// Everything the child needs, prepared before fork: after fork only
// async-signal-safe calls are allowed (another thread may hold malloc's lock).
struct ChildSetup {
    std::vector<std::string> arguments;
    std::vector<char*> argv;
    std::vector<std::string> environment;
    std::vector<char*> envp;
    std::string workDir;
    int unshareFlags = 0;
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

// Writes `text` to a /proc file with async-signal-safe calls only (the child of
// a multithreaded grader); failures are ignored: the child then runs unmapped.
void writeProcFile(const char* path, const std::string& text) {
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return;
    ssize_t written = write(fd, text.data(), text.size());
    (void)written;
    close(fd);
}

[[noreturn]] void runChild(const ChildSetup& setup, int outputFd, int errorFd) {
    setpgid(0, 0);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    struct sigaction defaultAction {};
    defaultAction.sa_handler = SIG_DFL;
    sigaction(SIGPIPE, &defaultAction, nullptr);
    sigaction(SIGINT, &defaultAction, nullptr);
    sigaction(SIGTERM, &defaultAction, nullptr);

    int input = open("/dev/null", O_RDONLY);
    if (input >= 0 && input != STDIN_FILENO) {
        dup2(input, STDIN_FILENO);
        close(input);
    }
    dup2(outputFd, STDOUT_FILENO);
    dup2(outputFd, STDERR_FILENO);
#ifdef SYS_close_range
    // Descriptors the grader inherited from its own parent stay out of the lab
    // program: close-on-exec for everything past stderr (Linux 5.11; ignored before).
    constexpr unsigned kCloseRangeCloexec = 1u << 2;
    syscall(SYS_close_range, 3u, ~0u, kCloseRangeCloexec);
#endif

    // No network: a fresh network namespace has only a loopback device, and it is
    // down. Before the limits, so that the new user namespace records the grader's
    // RLIMIT_NPROC for its parent level and the child's own applies inside it.
    if (setup.unshareFlags != 0 && unshare(setup.unshareFlags) == 0 && (setup.unshareFlags & CLONE_NEWUSER)) {
        writeProcFile("/proc/self/setgroups", "deny\n");   // required before gid_map
        writeProcFile("/proc/self/uid_map", setup.uidMap);
        writeProcFile("/proc/self/gid_map", setup.gidMap);
    }

    // On failure the parent learns the step (0: chdir, 1: exec) and errno.
    int failure[2] = {0, 0};
    if (!setup.workDir.empty() && chdir(setup.workDir.c_str()) != 0) {
        failure[1] = errno;
    } else {
        for (const ChildSetup::Limit& limit : setup.limits) setrlimit(limit.resource, &limit.value);
        execve(setup.argv[0], setup.argv.data(), setup.envp.data());
        failure[0] = 1;
        failure[1] = errno;
    }
    ssize_t written = write(errorFd, failure, sizeof failure);
    (void)written;
    _exit(127);
}

bool childHasEnded(pid_t pid) {
    siginfo_t info{};
    info.si_pid = 0;
    // WNOWAIT leaves the child a zombie, so its pid (and process group id)
    // cannot be reused before we kill what is left of the group.
    if (waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) != 0) return errno == ECHILD;
    return info.si_pid == pid;
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
    setup.arguments = argv;
    for (std::string& argument : setup.arguments) setup.argv.push_back(argument.data());
    setup.argv.push_back(nullptr);
    setup.workDir = workDir.string();
    if (limits.cpuSeconds > 0) setup.addLimit(RLIMIT_CPU, static_cast<rlim_t>(limits.cpuSeconds + 0.999));
    if (limits.addressSpaceBytes > 0) setup.addLimit(RLIMIT_AS, limits.addressSpaceBytes);
    if (limits.fileSizeBytes > 0) setup.addLimit(RLIMIT_FSIZE, limits.fileSizeBytes);
    setup.addLimit(RLIMIT_CORE, 0);
    setup.setEnvironment(limits.environment);
    if (limits.isolateNetwork) setup.unshareFlags = networkIsolationFlags();
    // RLIMIT_NPROC counts every task of the user; in the child's own user namespace
    // only the child's. It does not bind root: the watchdog below is the guard there.
    if (limits.maxTasks > 0 && getuid() != 0) {
        bool ownCount = (setup.unshareFlags & CLONE_NEWUSER) != 0;
        setup.addLimit(RLIMIT_NPROC, static_cast<rlim_t>(limits.maxTasks + (ownCount ? 0 : userTaskCount())));
    }

    Pipe output;
    Pipe execStatus;
    if (!output.valid() || !execStatus.valid()) {
        outcome.startError = std::string("could not create a pipe: ") + std::strerror(errno);
        return outcome;
    }

    Clock::time_point start = Clock::now();
    pid_t pid = fork();
    if (pid < 0) {
        outcome.startError = std::string("could not fork: ") + std::strerror(errno);
        return outcome;
    }
    if (pid == 0) runChild(setup, output.writeEnd(), execStatus.writeEnd());

    setpgid(pid, pid); // also done by the child; whichever runs first wins the race
    registerChild(pid);
    output.closeWrite();
    execStatus.closeWrite();

    // The status pipe closes on a successful exec (close-on-exec) and carries
    // the failing step and errno otherwise.
    int failure[2] = {0, 0};
    ssize_t got;
    while ((got = read(execStatus.readEnd(), failure, sizeof failure)) < 0 && errno == EINTR) {
    }
    if (got == static_cast<ssize_t>(sizeof failure)) {
        reap(pid);
        unregisterChild(pid);
        outcome.startError = failure[0] == 0
            ? "could not enter the work directory " + setup.workDir + ": " + std::strerror(failure[1])
            : "could not start " + argv[0] + ": " + std::strerror(failure[1]);
        outcome.seconds = secondsSince(start);
        return outcome;
    }

    fcntl(output.readEnd(), F_SETFL, fcntl(output.readEnd(), F_GETFL) | O_NONBLOCK);
    OutputCapture capture(limits.outputLimitBytes);
    bool pipeOpen = true;
    bool timedOut = false;
    bool tooManyProcesses = false;
    Clock::time_point lastCount = start;
    for (;;) {
        double remaining = limits.timeoutSeconds - secondsSince(start);
        if (remaining <= 0) {
            timedOut = true;
            break;
        }
        // Wake at least every 25 ms to notice a child that exited while a
        // grandchild still holds the pipe open.
        int waitMs = static_cast<int>(std::min(remaining * 1000.0 + 1.0, 25.0));
        pollfd entry{output.readEnd(), POLLIN, 0};
        poll(pipeOpen ? &entry : nullptr, pipeOpen ? 1 : 0, waitMs);
        if (pipeOpen) pipeOpen = drain(output.readEnd(), capture);
        if (childHasEnded(pid)) break;
        // The fork-bomb watchdog, ten times a second (it reads /proc).
        if (limits.maxProcesses > 0 && Clock::now() - lastCount >= std::chrono::milliseconds(100)) {
            lastCount = Clock::now();
            if (processGroupSize(pid) > limits.maxProcesses) {
                tooManyProcesses = true;
                break;
            }
        }
    }

    // Whatever is left of the group (the child if it timed out, grandchildren in
    // any case) goes now; then the last output is read and the child reaped.
    kill(-pid, SIGKILL);
    if (timedOut || tooManyProcesses) kill(pid, SIGKILL);
    int status = reap(pid);
    unregisterChild(pid);
    if (pipeOpen) drain(output.readEnd(), capture);

    outcome.seconds = secondsSince(start);
    outcome.output = printableText(capture.text());
    outcome.outputTruncated = capture.truncated();
    if (timedOut) {
        outcome.ending = ProcessEnding::TimedOut;
    } else if (tooManyProcesses) {
        outcome.ending = ProcessEnding::TooManyProcesses;
    } else if (WIFSIGNALED(status)) {
        outcome.ending = ProcessEnding::Signalled;
        outcome.signal = WTERMSIG(status);
    } else {
        outcome.ending = ProcessEnding::Exited;
        outcome.exitCode = WEXITSTATUS(status);
    }
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
