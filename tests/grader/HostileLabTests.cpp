// The grader against hostile lab programs: tests/grader/hostile_lab.cpp
// misbehaves in the way each case's name says. Every case must fail with a clear
// reason while the others still grade, the references must survive, and the
// grader must still write its results.

#include "catch.hpp"

#include "GradeCommand.hpp"
#include "Grader.hpp"
#include "HostileJob.hpp"
#include "FileSandbox.hpp"
#include "LabPlan.hpp"
#include "LabSandbox.hpp"
#include "ProcessContainment.hpp"
#include "TempFolder.hpp"

#include <stoa/image/Image.hpp>

#include <arpa/inet.h>
#include <sched.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <thread>

using namespace stoa::grader;
using stoa::Image;
using stoa::test::gradient;
using stoa::test::hostileJob;
using stoa::test::kHostileLab;

namespace {

std::string readAll(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

// A TCP socket listening on 127.0.0.1, to see whether a lab program can reach it.
class Listener {
public:
    Listener() {
        m_fd = socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof address;
        if (m_fd >= 0 && bind(m_fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
            listen(m_fd, 4) == 0 && getsockname(m_fd, reinterpret_cast<sockaddr*>(&address), &length) == 0)
            m_port = ntohs(address.sin_port);
    }
    ~Listener() {
        if (m_fd >= 0) close(m_fd);
    }
    int port() const { return m_port; }

private:
    int m_fd = -1;
    int m_port = 0;
};

// The files in `folder`, by name, with their contents.
std::map<std::string, std::string> contentsOf(const std::filesystem::path& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        files[entry.path().filename().string()] = readAll(entry.path());
    return files;
}

// The processes but this one whose environment holds `marker` (a zombie's reads empty).
std::vector<std::string> processesWith(const std::string& marker) {
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
        std::string pid = entry.path().filename().string();
        if (pid.find_first_not_of("0123456789") != std::string::npos || pid == std::to_string(getpid())) continue;
        if (readAll(entry.path() / "environ").find(marker) != std::string::npos)
            found.push_back(pid + " " + readAll(entry.path() / "comm"));
    }
    return found;
}

// Sets what the daemon cases of hostile_lab read (see its header): files to
// forge, the references, a one-second delay, and a marker to find them by.
std::string armDaemons(const std::vector<std::filesystem::path>& targets, const std::filesystem::path& references) {
    std::string list;
    for (const std::filesystem::path& target : targets) list += (list.empty() ? "" : ":") + target.string();
    std::string marker = "stoa-daemon-" + std::to_string(getpid()) + "-" +
                         std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
    setenv("STOA_HOSTILE_TARGETS", list.c_str(), 1);
    setenv("STOA_HOSTILE_REFERENCES", references.c_str(), 1);
    setenv("STOA_HOSTILE_DELAY", "1", 1);
    setenv("STOA_HOSTILE_MARK", marker.c_str(), 1);
    return marker;
}

void disarmDaemons() {
    for (const char* name : {"STOA_HOSTILE_TARGETS", "STOA_HOSTILE_DELAY", "STOA_HOSTILE_MARK"}) unsetenv(name);
}

// Longer than the daemons' delay: had one survived, it would have written by then.
void outwaitDaemons() { std::this_thread::sleep_for(std::chrono::milliseconds(2500)); }

const char* const kCases[] = {"good",          "segfault",         "abort",          "infinite_loop",
                              "memory_bomb",   "fork_bomb",        "uncaught_exception", "wrong_size",
                              "write_references", "garbage_output", "gl_error",       "network"};

} // namespace

TEST_CASE("hostile lab programs: each misdeed fails its case with a clear reason, the rest still grade",
          "[grader][isolation]") {
    stoa::test::TempFolder folder("hostile");
    std::filesystem::path references = folder.path() / "references" / "99_hostile";
    std::filesystem::create_directories(references);
    std::vector<CaseJob> jobs;
    for (const char* name : kCases) {
        jobs.push_back(hostileJob(name, references, folder.path() / "work"));
    }
    std::map<std::string, std::string> before;
    for (const auto& entry : std::filesystem::directory_iterator(references))
        before[entry.path().filename().string()] = readAll(entry.path());

    Listener listener;
    REQUIRE(listener.port() > 0);
    setenv("STOA_HOSTILE_PORT", std::to_string(listener.port()).c_str(), 1);
    setenv("STOA_HOSTILE_REFERENCES", references.c_str(), 1);

    RunSettings settings;
    // 6 s: enough for every quick misdeed to end on its own on a loaded 2-core machine
    // (with 3 s, an abort was once reported as a timeout there).
    settings.limits = defaultLimits(6.0);
    settings.limits.addressSpaceBytes = 512ull << 20;  // the memory bomb stops at 512 MiB
    auto start = std::chrono::steady_clock::now();
    std::vector<GradeResult> results = gradeCases(jobs, settings, 3);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    REQUIRE(results.size() == jobs.size());
    std::map<std::string, GradeResult> byName;
    for (const GradeResult& result : results) byName[result.caseName] = result;
    auto reasonOf = [&](const std::string& name) {
        INFO(name << ": " << statusName(byName[name].status) << ": " << byName[name].reason);
        CHECK(byName[name].points == 0);
        return byName[name].reason;
    };

    CHECK(byName["good"].status == GradeStatus::Passed);
    CHECK(byName["good"].points == 1);
    for (const GradeResult& result : results) {
        if (result.caseName == "good") continue;
        INFO(result.caseName << ": " << result.reason);
        CHECK(result.status == GradeStatus::Error);
        CHECK_FALSE(result.reason.empty());
        CHECK(printableText(result.reason) == result.reason);
        CHECK(printableText(result.programOutput) == result.programOutput);
    }
    // Matchers, so that a failure prints the reason the grader gave.
    using Catch::Matchers::Contains;
    using Catch::Matchers::Equals;
    using Catch::Matchers::StartsWith;
    CHECK_THAT(reasonOf("segfault"), StartsWith("crashed with SIGSEGV"));
    CHECK_THAT(reasonOf("abort"), StartsWith("crashed with SIGABRT"));
    CHECK_THAT(reasonOf("infinite_loop"), StartsWith("too slow: still computing when its limit of 6 s ran out ("));
    CHECK_THAT(reasonOf("memory_bomb"), Contains("bad_alloc"));
    CHECK_THAT(reasonOf("fork_bomb"), Contains("started more than"));
    CHECK_THAT(reasonOf("uncaught_exception"), Contains("a student's bug"));
    CHECK_THAT(reasonOf("wrong_size"), Equals("rendered 8x4, expected 16x16"));
    CHECK_THAT(reasonOf("write_references"), Contains("tried to modify the reference images"));
    CHECK_THAT(reasonOf("garbage_output"), StartsWith("exited with status 1"));
    CHECK(byName["garbage_output"].programOutput.size() < 3 * 4096 + 200);
    CHECK_THAT(reasonOf("gl_error"),
               Equals("exited with status 1: lab99_hostile: glDrawElements (Renderer.cpp:42): GL_INVALID_OPERATION"));
    if (networkIsolationFlags() != 0) CHECK_THAT(reasonOf("network"), Contains("no network"));
    else WARN(networkIsolationNote());

    // The references are back as they were, and the planted file is gone.
    std::map<std::string, std::string> after;
    for (const auto& entry : std::filesystem::directory_iterator(references))
        after[entry.path().filename().string()] = readAll(entry.path());
    CHECK(after == before);
    // Nothing waited for the full timeout but the infinite loop (3 cases at once).
    CHECK(seconds < 20.0);
}

namespace {

// A classmate's file, a solution and a grade that hostile_lab's cases try to
// read or overwrite while confined as in a class batch (the submissions and the
// grades private, as stoa-grade-class makes them); Landlock, or the mount
// namespace that stands in for it (`preferMounts`).
void checkConfined(bool preferMounts) {
    stoa::test::TempFolder folder("hostile-files");
    const std::string classmateSource = "void secret() {}\n";
    const std::string solution = "// the solution\n";
    const std::string grades = "{\"score\": 3}\n";
    std::filesystem::path classmate = folder.write("submissions/zzz_victim/labs/01_transforms/student/transforms.cpp",
                                                   classmateSource);
    std::filesystem::path tree = folder.path() / "stoa";
    std::filesystem::path solutionFile = folder.write("stoa/solutions/01_transforms/student/transforms.cpp", solution);
    std::filesystem::path resultsFile = folder.write("grades/aaa_mallory/results.json", grades);
    setenv("STOA_HOSTILE_CLASSMATE", classmate.c_str(), 1);
    setenv("STOA_HOSTILE_SOLUTIONS", solutionFile.c_str(), 1);
    setenv("STOA_HOSTILE_RESULTS", resultsFile.c_str(), 1);

    std::filesystem::path work = folder.path() / "grades" / "aaa_mallory" / "work";
    std::filesystem::path references = folder.path() / "references" / "99_hostile";
    std::vector<CaseJob> jobs;
    for (const char* name : {"good", "read_classmate", "write_solutions", "write_grades", "see_grader"})
        jobs.push_back(hostileJob(name, references, work));
    RunSettings settings;
    settings.limits = defaultLimits(10.0);
    settings.sourceDir = tree;
    settings.files = labProgramBaseAccess(tree, work);
    settings.files.excluded.push_back(folder.path() / "submissions");
    settings.files.excluded.push_back(folder.path() / "grades");
    settings.files.preferMounts = preferMounts;
    std::vector<GradeResult> results = gradeCases(jobs, settings, 2);
    std::map<std::string, GradeResult> byName;
    for (const GradeResult& result : results) byName[result.caseName] = result;

    using Catch::Matchers::Contains;
    INFO("good: " << byName["good"].reason);
    CHECK(byName["good"].status == GradeStatus::Passed);
    for (const char* name : {"read_classmate", "write_solutions", "write_grades"}) {
        INFO(name << ": " << statusName(byName[name].status) << ": " << byName[name].reason);
        CHECK(byName[name].status == GradeStatus::Error);
        CHECK_THAT(byName[name].reason, Contains(name[0] == 'r' ? "cannot read" : "cannot write"));
        // Landlock refuses; the mounts hide (no such file) or refuse a write (read-only).
        if (!preferMounts) CHECK_THAT(byName[name].reason, Contains("Permission denied"));
    }
    // With a PID and a mount namespace the program's /proc is its own.
    if ((pidNamespaceFlags() & CLONE_NEWNS) != 0) {
        INFO("see_grader: " << byName["see_grader"].reason);
        CHECK(byName["see_grader"].status == GradeStatus::Error);
        CHECK_THAT(byName["see_grader"].reason, Contains("not among the processes"));
    }
    CHECK(readAll(classmate) == classmateSource);
    CHECK(readAll(solutionFile) == solution);
    CHECK(readAll(resultsFile) == grades);
    for (const char* name : {"STOA_HOSTILE_CLASSMATE", "STOA_HOSTILE_SOLUTIONS", "STOA_HOSTILE_RESULTS"})
        unsetenv(name);
}

} // namespace

TEST_CASE("confined lab programs: a classmate's file, solutions/ and the grades stay out of reach",
          "[grader][isolation]") {
    if (!filesCanBeConfined()) {
        WARN(fileConfinementNote());
        return;
    }
    checkConfined(false);
}

TEST_CASE("confined lab programs without Landlock: a mount namespace keeps the same files out of reach",
          "[grader][isolation]") {
    if ((pidNamespaceFlags() & CLONE_NEWNS) == 0) {
        WARN("no mount namespace for the lab programs here: the fallback cannot be tried");
        return;
    }
    checkConfined(true);
}

TEST_CASE("treeWithout grants a tree but the subtrees carved out of it", "[grader][isolation]") {
    stoa::test::TempFolder folder("tree-without");
    folder.write("build/bin/lab01", "x");
    folder.write("build/class/alice/work/a.png", "x");
    folder.write("build/class/bob/results.json", "x");
    folder.write("build/CMakeCache.txt", "x");
    std::filesystem::path root = std::filesystem::weakly_canonical(folder.path());
    std::vector<std::filesystem::path> granted =
        treeWithout(root / "build", {root / "build" / "class" / "alice", root / "nowhere"});
    std::sort(granted.begin(), granted.end());
    CHECK(granted == std::vector<std::filesystem::path>{root / "build" / "CMakeCache.txt", root / "build" / "bin",
                                                        root / "build" / "class" / "bob"});
    // Nothing carved below: the tree itself. An excluded folder around it does not remove it.
    CHECK(treeWithout(root / "build" / "bin", {root / "build"}) ==
          std::vector<std::filesystem::path>{root / "build" / "bin"});
}

TEST_CASE("printableText keeps text and replaces binary and control bytes", "[grader][isolation]") {
    CHECK(printableText("plain\ttext\n") == "plain\ttext\n");
    CHECK(printableText("caf\xC3\xA9 \xE2\x9C\x93") == "caf\xC3\xA9 \xE2\x9C\x93");
    CHECK(printableText("a\r\nb\rc") == "a\nb\nc");
    CHECK(printableText(std::string("nul\0bell\x07", 9)) == "nul?bell?");
    CHECK(printableText("\xFF\xFE") == "\xEF\xBF\xBD\xEF\xBF\xBD");
    CHECK(printableText("cut \xE2\x9C") == "cut \xEF\xBF\xBD\xEF\xBF\xBD");   // truncated mid-character
    CHECK(printableText("\xC0\xAF") == "\xEF\xBF\xBD\xEF\xBF\xBD");           // overlong '/'
    CHECK(printableText("\x1B[31mred") == "?[31mred");
}

TEST_CASE("the grader writes results.json itself, after every lab program has ended", "[grader][isolation]") {
    stoa::test::TempFolder folder("hostile-results");
    folder.write("labs/99_hostile/cases.ini",
                 "lab = 99_hostile\ntitle = Hostile\n\n"
                 "[case good]\nresolution = 16 16\npoints = 1\n\n"
                 "[case write_results]\nresolution = 16 16\npoints = 1\n\n"
                 "[case segfault]\nresolution = 16 16\npoints = 1\n");
    std::filesystem::create_directories(folder.path() / "autograder/references/99_hostile");
    for (const char* name : {"good", "write_results", "segfault"})
        gradient(16, 16).savePng(folder.path() / "autograder/references/99_hostile" / (std::string(name) + ".png"));
    std::filesystem::create_directories(folder.path() / "bin");
    std::filesystem::create_symlink(kHostileLab, folder.path() / "bin/lab99_hostile");
    std::filesystem::path json = folder.path() / "results/results.json";
    std::filesystem::create_directories(json.parent_path());
    setenv("STOA_HOSTILE_RESULTS", json.c_str(), 1);

    Options options;
    options.jsonFile = json;
    options.workDir = folder.path() / "work";
    options.timeoutSeconds = 10;
    std::ostringstream out;
    std::ostringstream err;
    Environment env{folder.path(), folder.path() / "bin", out, err};
    CHECK(runGrade(options, env) == 0);
    std::string written = readAll(json);
    INFO(written);
    CHECK(written.find("\"forged\"") == std::string::npos);
    CHECK(written.find("\"score\": 1") != std::string::npos);
    CHECK(written.find("crashed with SIGSEGV") != std::string::npos);
    CHECK(out.str().find("segfault") != std::string::npos);
}

TEST_CASE("hostile daemons: a double-forked setsid() daemon is killed and fails its case",
          "[grader][isolation]") {
    stoa::test::TempFolder folder("hostile-daemons");
    std::filesystem::path references = folder.path() / "references" / "99_hostile";
    std::filesystem::create_directories(references);
    std::filesystem::path reports = folder.path() / "reports";
    std::vector<std::filesystem::path> targets;
    for (const char* name : {"results.json", "report.html", "gradebook.csv"}) {
        targets.push_back(reports / name);
        folder.write("reports/" + std::string(name), std::string("written by the grader: ") + name + "\n");
    }
    std::vector<CaseJob> jobs;
    for (const char* name : {"good", "daemon_rewrite", "daemon_refork", "daemon_stealth"}) {
        jobs.push_back(hostileJob(name, references, folder.path() / "work"));
    }
    std::map<std::string, std::string> referencesBefore = contentsOf(references);
    std::map<std::string, std::string> reportsBefore = contentsOf(reports);
    std::string marker = armDaemons(targets, references);

    // Both guards: the PID namespace (where the system allows one), and the
    // subreaper's sweep alone (one case at a time, so that the blame is exact).
    for (bool ownPidNamespace : {true, false}) {
        RunSettings settings;
        settings.limits = defaultLimits(10.0);
        settings.limits.ownPidNamespace = ownPidNamespace;
        auto start = std::chrono::steady_clock::now();
        std::vector<GradeResult> results = gradeCases(jobs, settings, ownPidNamespace ? 2 : 1);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        REQUIRE(results.size() == jobs.size());
        for (const GradeResult& result : results) {
            INFO("own PID namespace: " << ownPidNamespace << ", " << result.caseName << ": "
                 << statusName(result.status) << ": " << result.reason);
            if (result.caseName == "good") {
                CHECK(result.status == GradeStatus::Passed);
                continue;
            }
            CHECK(result.status == GradeStatus::Error);
            CHECK(result.points == 0);
            CHECK_THAT(result.reason, Catch::Matchers::StartsWith("the lab program left "));
            CHECK_THAT(result.reason, Catch::Matchers::Contains("running after it exited (killed)"));
        }
        CHECK(processesWith(marker).empty());
        CHECK(seconds < 10.0);   // nothing waited for the daemons' delay
    }
    outwaitDaemons();
    disarmDaemons();
    CHECK(processesWith(marker).empty());
    CHECK(contentsOf(reports) == reportsBefore);
    CHECK(contentsOf(references) == referencesBefore);
}

TEST_CASE("hostile daemons: the reports are written after every process of the lab programs has ended",
          "[grader][isolation]") {
    stoa::test::TempFolder folder("hostile-daemon-reports");
    folder.write("labs/99_hostile/cases.ini",
                 "lab = 99_hostile\ntitle = Hostile\n\n"
                 "[case good]\nresolution = 16 16\npoints = 1\n\n"
                 "[case daemon_rewrite]\nresolution = 16 16\npoints = 1\n\n"
                 "[case daemon_stealth]\nresolution = 16 16\npoints = 1\n");
    std::filesystem::path references = folder.path() / "autograder/references/99_hostile";
    std::filesystem::create_directories(references);
    for (const char* name : {"good", "daemon_rewrite", "daemon_stealth"})
        gradient(16, 16).savePng(references / (std::string(name) + ".png"));
    std::filesystem::create_directories(folder.path() / "bin");
    std::filesystem::create_symlink(kHostileLab, folder.path() / "bin/lab99_hostile");
    std::filesystem::path results = folder.path() / "results";
    folder.write("results/gradebook.csv", "student,total\nsomeone,1\n");

    Options options;
    options.jsonFile = results / "results.json";
    options.htmlFile = results / "report.html";
    options.junitFile = results / "junit.xml";
    options.workDir = folder.path() / "work";
    options.timeoutSeconds = 10;
    std::string marker = armDaemons({options.jsonFile, options.htmlFile, options.junitFile,
                                     results / "gradebook.csv"}, references);
    std::map<std::string, std::string> referencesBefore = contentsOf(references);
    std::ostringstream out;
    std::ostringstream err;
    Environment env{folder.path(), folder.path() / "bin", out, err};
    CHECK(runGrade(options, env) == 0);
    std::map<std::string, std::string> written = contentsOf(results);
    REQUIRE(written.size() == 4);   // no temporary file left beside them
    INFO(written["results.json"]);
    CHECK(written["results.json"].find("\"score\": 1,") != std::string::npos);
    CHECK(written["results.json"].find("left 1 process running after it exited (killed)") != std::string::npos);
    CHECK(written["report.html"].find("<html") != std::string::npos);

    outwaitDaemons();
    disarmDaemons();
    CHECK(processesWith(marker).empty());
    CHECK(contentsOf(results) == written);
    CHECK(contentsOf(references) == referencesBefore);
}
