// The child-process runner, with /bin/sh commands standing in for lab programs.

#include "catch.hpp"

#include "ChildProcess.hpp"
#include "Grader.hpp"
#include "TempFolder.hpp"

#include <chrono>
#include <csignal>
#include <thread>

using namespace stoa::grader;

namespace {

ProcessOutcome runShell(const std::string& script, const ProcessLimits& limits = defaultLimits(10.0),
                        const std::filesystem::path& workDir = {}) {
    return runProcess({"/bin/sh", "-c", script}, workDir, limits);
}

ProcessLimits withTimeout(double seconds) {
    ProcessLimits limits = defaultLimits(seconds);
    return limits;
}

} // namespace

TEST_CASE("runProcess: a process that exits 0 has its output captured", "[grader][process]") {
    ProcessOutcome outcome = runShell("echo hello; echo world >&2");
    CHECK(outcome.ending == ProcessEnding::Exited);
    CHECK(outcome.exitedWith(0));
    CHECK(outcome.output == "hello\nworld\n");
    CHECK_FALSE(outcome.outputTruncated);
    CHECK(outcome.describe() == "exited with status 0");
}

TEST_CASE("runProcess: exit 3 keeps the stub's last line", "[grader][process]") {
    ProcessOutcome outcome =
        runShell("echo rendering; echo 'stoa: not implemented: Camera::viewMatrix()' >&2; exit 3");
    CHECK(outcome.exitedWith(3));
    CHECK(outcome.lastOutputLine() == "stoa: not implemented: Camera::viewMatrix()");
    CHECK(outcome.describe() == "exited with status 3");
}

TEST_CASE("runProcess: a segfault is reported with the signal's name", "[grader][process]") {
    ProcessOutcome outcome = runShell("kill -SEGV $$");
    REQUIRE(outcome.ending == ProcessEnding::Signalled);
    CHECK(outcome.signal == SIGSEGV);
    CHECK(outcome.describe().rfind("crashed with SIGSEGV (segmentation fault", 0) == 0);
}

TEST_CASE("runProcess: a process past the timeout is killed, with its children", "[grader][process]") {
    auto start = std::chrono::steady_clock::now();
    // The shell's child `sleep` holds the pipe open too; the whole group must go.
    ProcessOutcome outcome = runShell("echo started; sleep 30; echo never", withTimeout(1.0));
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(outcome.ending == ProcessEnding::TimedOut);
    CHECK(outcome.describe() == "timed out after 1 s");
    CHECK(outcome.output == "started\n");
    CHECK(seconds >= 0.9);
    CHECK(seconds < 5.0);
}

TEST_CASE("runProcess: a grandchild that keeps the pipe open does not hold the grader", "[grader][process]") {
    auto start = std::chrono::steady_clock::now();
    ProcessOutcome outcome = runShell("sleep 30 & echo done", withTimeout(20.0));
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(outcome.exitedWith(0));
    CHECK(outcome.output == "done\n");
    CHECK(outcome.strayProcesses == 1);   // the sleep, killed
    CHECK(seconds < 5.0);
}

TEST_CASE("runProcess: a setsid() daemon does not outlive the program, with or without a PID namespace",
          "[grader][process]") {
    stoa::test::TempFolder folder("daemon");
    // Forks, leaves the group and the session, forks again, then writes after a second.
    const std::string script = "(setsid sh -c 'sleep 1; echo forged > \"$0\"' \"$1\" &); echo started";
    std::vector<std::filesystem::path> files;
    for (bool ownPidNamespace : {true, false}) {
        ProcessLimits limits = withTimeout(10.0);
        limits.ownPidNamespace = ownPidNamespace;
        files.push_back(folder.path() / (ownPidNamespace ? "namespace" : "subreaper"));
        ProcessOutcome outcome = runProcess({"/bin/sh", "-c", script, "sh", files.back().string()}, {}, limits);
        INFO("own PID namespace: " << ownPidNamespace << ", " << outcome.describe() << ": " << outcome.output);
        CHECK(outcome.exitedWith(0));
        CHECK(outcome.strayProcesses >= 1);   // sh -c and its sleep, as the kill finds them
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2000));
    for (const std::filesystem::path& file : files) CHECK_FALSE(std::filesystem::exists(file));
}

TEST_CASE("runProcess: flooding stdout is truncated to a few kilobytes", "[grader][process]") {
    ProcessOutcome outcome = runShell("head -c 3000000 /dev/zero | tr '\\000' x; echo; echo last line");
    CHECK(outcome.exitedWith(0));
    CHECK(outcome.outputTruncated);
    CHECK(outcome.output.size() < 4096 + 100);
    CHECK(outcome.output.find("bytes of output left out") != std::string::npos);
    CHECK(outcome.output.rfind("xxxx", 0) == 0);               // the head is kept
    CHECK(outcome.lastOutputLine() == "last line");            // and so is the tail
}

TEST_CASE("runProcess: a program that does not exist fails to start with a reason", "[grader][process]") {
    ProcessOutcome outcome = runProcess({"/nonexistent/lab99_nothing", "--list"}, {}, defaultLimits(5.0));
    CHECK(outcome.ending == ProcessEnding::FailedToStart);
    CHECK(outcome.describe().find("/nonexistent/lab99_nothing") != std::string::npos);
    CHECK(outcome.describe().find("No such file") != std::string::npos);

    ProcessOutcome empty = runProcess({}, {}, defaultLimits(5.0));
    CHECK(empty.ending == ProcessEnding::FailedToStart);
}

TEST_CASE("runProcess: runs in the work folder with stdin closed", "[grader][process]") {
    stoa::test::TempFolder folder;
    ProcessOutcome outcome = runShell("pwd; cat; echo end", defaultLimits(5.0), folder.path());
    CHECK(outcome.exitedWith(0));
    CHECK(outcome.output == std::filesystem::canonical(folder.path()).string() + "\nend\n");

    ProcessOutcome missing = runShell("pwd", defaultLimits(5.0), folder.path() / "missing");
    CHECK(missing.ending == ProcessEnding::FailedToStart);
    CHECK(missing.describe().find("work directory") != std::string::npos);
}

TEST_CASE("runProcess: the resource limits apply in the child", "[grader][process]") {
    SECTION("CPU time") {
        ProcessLimits limits = defaultLimits(20.0);
        limits.cpuSeconds = 1.0;
        ProcessOutcome outcome = runShell("while :; do :; done", limits);
        REQUIRE(outcome.ending == ProcessEnding::Signalled);
        CHECK(outcome.signal == SIGXCPU);
        CHECK(outcome.describe().find("CPU time limit") != std::string::npos);
    }
    SECTION("file size") {
        stoa::test::TempFolder folder;
        ProcessLimits limits = defaultLimits(10.0);
        limits.fileSizeBytes = 64 * 1024;
        ProcessOutcome outcome = runShell("exec head -c 1000000 /dev/zero > big.bin", limits, folder.path());
        REQUIRE(outcome.ending == ProcessEnding::Signalled);
        CHECK(outcome.signal == SIGXFSZ);
        CHECK(std::filesystem::file_size(folder.path() / "big.bin") <= 64 * 1024);
    }
    SECTION("core dumps are off") {
        ProcessOutcome outcome = runShell("ulimit -c");
        CHECK(outcome.output == "0\n");
    }
}

TEST_CASE("forEachInParallel runs the tasks at once", "[grader][process]") {
    std::vector<ProcessOutcome> outcomes(4);
    auto start = std::chrono::steady_clock::now();
    forEachInParallel(outcomes.size(), 4, [&](std::size_t i) {
        outcomes[i] = runShell("sleep 0.5; echo " + std::to_string(i));
    });
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (std::size_t i = 0; i < outcomes.size(); ++i) CHECK(outcomes[i].output == std::to_string(i) + "\n");
    CHECK(seconds < 1.5);
}

TEST_CASE("describeSignal names common signals", "[grader][process]") {
    CHECK(describeSignal(SIGABRT).rfind("SIGABRT (abort", 0) == 0);
    CHECK(describeSignal(SIGFPE).rfind("SIGFPE", 0) == 0);
    CHECK(describeSignal(77) == "signal 77");
}
