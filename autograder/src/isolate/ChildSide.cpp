#include "ChildSide.hpp"

#include "FileSandbox.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <sys/wait.h>

namespace stoa::grader {

namespace {

// Writes `text` to a /proc file with async-signal-safe calls only (the child of
// a multithreaded grader); failures are ignored: the child then runs unmapped.
void writeProcFile(const char* path, const std::string& text) {
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0) return;
    ssize_t written = write(fd, text.data(), text.size());
    (void)written;
    close(fd);
}

// The program's side: the work folder, the limits, the file sandbox, exec. On
// failure the grader learns the step (0: chdir, 1: exec or fork, 2: the
// sandbox) and errno through `errorFd`.
[[noreturn]] void execProgram(const ChildSetup& setup, int errorFd) {
    int failure[2] = {0, 0};
    // The mounts first: a work folder entered before them would still be the
    // one on the read-only mount below the bind that makes it writable.
    int confined = setup.mountSandbox ? setup.mountSandbox->enter() : 0;
    if (confined != 0) {
        failure[0] = 2;
        failure[1] = confined;
    } else if (!setup.workDir.empty() && chdir(setup.workDir.c_str()) != 0) {
        failure[1] = errno;
    } else {
        for (const ChildSetup::Limit& limit : setup.limits) setrlimit(limit.resource, &limit.value);
        confined = setup.fileSandbox >= 0 ? enterFileSandbox(setup.fileSandbox) : 0;
        if (confined != 0) {
            failure[0] = 2;
            failure[1] = confined;
        } else {
            execve(setup.argv[0], setup.argv.data(), setup.envp.data());
            failure[0] = 1;
            failure[1] = errno;
        }
    }
    ssize_t written = write(errorFd, failure, sizeof failure);
    (void)written;
    _exit(127);
}

[[noreturn]] void reportForkFailure(int errorFd) {
    int failure[2] = {1, errno};
    ssize_t written = write(errorFd, failure, sizeof failure);
    (void)written;
    _exit(127);
}

// Process 1 of the child's own PID namespace. It starts the program as process
// 2 and waits for it; then whatever the program left in the namespace (a
// setsid() daemon cannot leave a PID namespace) is killed and reaped, and the
// grader gets the program's wait status and how many were still running
// through `reportFd`. Were this process to die, the kernel would kill the rest
// of the namespace too; the program cannot kill it (a namespace's process 1
// ignores the signals its namespace sends it without a handler, SIGKILL included).
[[noreturn]] void runNamespaceInit(const ChildSetup& setup, int errorFd, int reportFd) {
    // A /proc of this namespace, in a mount namespace of its own (private first,
    // so that nothing propagates back): the grader's processes, their command
    // lines and folders are not in it. Should the mount fail, Landlock still
    // keeps the program out of their files (FileSandbox.hpp).
    if (setup.unshareFlags & CLONE_NEWNS) {
        if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0)
            mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr);
    }
    // The one process of the grader's in the program's /proc is this one: its
    // name and command line say nothing of the grader's.
    prctl(PR_SET_NAME, "stoa-init", 0, 0, 0);
    static const char kName[] = "stoa-init";
    if (setup.graderArguments && setup.graderArgumentsLength >= sizeof kName) {
        memset(setup.graderArguments, 0, setup.graderArgumentsLength);
        memcpy(setup.graderArguments, kName, sizeof kName);
    }
    pid_t program = fork();
    if (program == 0) execProgram(setup, errorFd);
    if (program < 0) reportForkFailure(errorFd);
    close(errorFd);
    close(STDOUT_FILENO);
    close(STDERR_FILENO);
    int status = 0;
    while (waitpid(program, &status, 0) < 0 && errno == EINTR) {
    }
    // Children that ended before the program did were not left running.
    while (waitpid(-1, nullptr, WNOHANG) > 0) {
    }
    int left = 0;
    if (kill(-1, SIGKILL) == 0) {   // every process of the namespace but this one
        for (;;) {
            if (waitpid(-1, nullptr, 0) > 0) ++left;
            else if (errno != EINTR) break;
        }
    }
    int report[2] = {status, left};
    ssize_t written = write(reportFd, report, sizeof report);
    (void)written;
    _exit(0);
}

} // namespace

[[noreturn]] void runChild(const ChildSetup& setup, int outputFd, int errorFd, int reportFd) {
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
    // Descriptors the grader inherited from its own parent, or opened without
    // O_CLOEXEC in another thread (a report being written), stay out of the lab
    // program: close-on-exec for everything past stderr. close_range needs Linux
    // 5.11; before it, every descriptor up to the limit is marked one by one.
    bool marked = false;
#ifdef SYS_close_range
    constexpr unsigned kCloseRangeCloexec = 1u << 2;
    marked = syscall(SYS_close_range, 3u, ~0u, kCloseRangeCloexec) == 0;
#endif
    if (!marked)
        for (int fd = 3; fd < setup.descriptorLimit; ++fd) fcntl(fd, F_SETFD, FD_CLOEXEC);

    // No network: a fresh network namespace has only a loopback device, and it is
    // down. Before the limits, so that the new user namespace records the grader's
    // RLIMIT_NPROC for its parent level and the child's own applies inside it.
    bool ownPids = false;
    if (setup.unshareFlags != 0 && unshare(setup.unshareFlags) == 0) {
        if (setup.unshareFlags & CLONE_NEWUSER) {
            writeProcFile("/proc/self/setgroups", "deny\n");   // required before gid_map
            writeProcFile("/proc/self/uid_map", setup.uidMap);
            writeProcFile("/proc/self/gid_map", setup.gidMap);
        }
        ownPids = (setup.unshareFlags & CLONE_NEWPID) != 0;
    }
    if (!ownPids) execProgram(setup, errorFd);

    // unshare(CLONE_NEWPID) puts this process's next child, not itself, in the new
    // namespace: that child is the namespace's process 1. This process waits for
    // it and ends the way it ended, so that the grader sees a killed init as killed.
    pid_t init = fork();
    if (init == 0) runNamespaceInit(setup, errorFd, reportFd);
    if (init < 0) reportForkFailure(errorFd);
    close(errorFd);
    close(reportFd);
    close(STDOUT_FILENO);
    close(STDERR_FILENO);
    int status = 0;
    while (waitpid(init, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status)) {
        rlimit noCore{0, 0};
        setrlimit(RLIMIT_CORE, &noCore);
        kill(getpid(), WTERMSIG(status));
    }
    _exit(WIFEXITED(status) ? WEXITSTATUS(status) : 127);
}

} // namespace stoa::grader
