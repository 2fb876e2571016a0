// A "lab program" that misbehaves on purpose, for the grader's isolation tests.
// It takes the lab CLI (--render CASE --output FILE [--backend NAME]) and does
// what the case's name says. "good" and the cheats render a 16x16 gradient (the
// tests' reference); the environment tells it where the real files are, as a
// student who knows the repository's layout would:
//   STOA_HOSTILE_REFERENCES  a folder of reference images to overwrite
//   STOA_HOSTILE_RESULTS     the results file to forge
//   STOA_HOSTILE_PORT        a TCP port on 127.0.0.1 that the test listens on
//   STOA_HOSTILE_CLASSMATE   a classmate's source file to read (read_classmate)
//   STOA_HOSTILE_SOLUTIONS   a file in solutions/ to overwrite (write_solutions)
// Those two, write_grades (STOA_HOSTILE_RESULTS) and see_grader (a process
// named stoa-tests* in /proc) render the right picture only when they get
// what they tried for; refused, they exit 1 saying what was refused.
// The daemon cases (daemon_rewrite, daemon_refork, daemon_stealth, or any case
// when STOA_HOSTILE_DAEMON names one of them) leave a process behind that, after
// STOA_HOSTILE_DELAY seconds (default 1), overwrites with a perfect score every
// report named by --json, --html, --junit on its ancestors' command lines, the
// files in STOA_HOSTILE_TARGETS (':'-separated) and the references, if it is
// still alive: the attack of issue 15, with the delay made short for the tests.

#include <stoa/image/Image.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

stoa::Image gradient(int width, int height, int shift = 0) {
    stoa::Image image(width, height, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.setPixel(x, y, {static_cast<std::uint8_t>((x * 16 + shift) & 255),
                                  static_cast<std::uint8_t>(y * 16), 128, 255});
    return image;
}

const char* environment(const char* name) {
    const char* value = std::getenv(name);
    if (!value) {
        std::fprintf(stderr, "hostile_lab: %s is not set\n", name);
        std::exit(1);
    }
    return value;
}

// Overwrites every reference with a wrong image, then renders the same wrong
// image: without the grader's guard, the case would pass.
int overwriteReferences(const std::string& output) {
    stoa::Image wrong = gradient(16, 16, 128);
    for (const auto& entry : std::filesystem::directory_iterator(environment("STOA_HOSTILE_REFERENCES")))
        if (entry.path().extension() == ".png") wrong.savePng(entry.path());
    std::ofstream(std::filesystem::path(environment("STOA_HOSTILE_REFERENCES")) / "planted.png") << "x";
    wrong.savePng(output);
    return 0;
}

std::string readFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// The reports the ancestors write: the value after --json, --html or --junit on
// their command lines, made absolute with their working folder. The ancestors
// come from /proc/self/stat rather than getppid(), which answers 1 inside a PID
// namespace while /proc still shows the real parent.
std::vector<std::string> ancestorReports() {
    std::vector<std::string> reports;
    std::string pid = "self";
    for (int depth = 0; depth < 16; ++depth) {
        std::string stat = readFile("/proc/" + pid + "/stat");
        std::size_t close = stat.rfind(')');
        if (close == std::string::npos) break;
        std::istringstream fields(stat.substr(close + 1));
        std::string state;
        long parent = 0;
        fields >> state >> parent;
        if (parent <= 1) break;
        pid = std::to_string(parent);
        std::string cmdline = readFile("/proc/" + pid + "/cmdline");
        std::error_code error;
        std::filesystem::path cwd = std::filesystem::read_symlink("/proc/" + pid + "/cwd", error);
        std::vector<std::string> words;
        for (std::size_t at = 0; at < cmdline.size();) {
            std::size_t end = cmdline.find('\0', at);
            if (end == std::string::npos) end = cmdline.size();
            words.push_back(cmdline.substr(at, end - at));
            at = end + 1;
        }
        for (std::size_t i = 0; i + 1 < words.size(); ++i)
            if (words[i] == "--json" || words[i] == "--html" || words[i] == "--junit")
                reports.push_back((cwd / words[i + 1]).string());
    }
    return reports;
}

// What the daemon does once it has waited: a perfect score everywhere it can write.
void forgeEverything(const std::vector<std::string>& reports) {
    for (const std::string& path : reports)
        std::ofstream(path, std::ios::binary | std::ios::trunc) << "{\"score\": 100, \"tests\": []}\n";
    if (const char* references = std::getenv("STOA_HOSTILE_REFERENCES")) {
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator(references, error))
            if (entry.path().extension() == ".png") std::ofstream(entry.path(), std::ios::binary) << "forged";
    }
}

double delaySeconds() {
    const char* delay = std::getenv("STOA_HOSTILE_DELAY");
    return delay ? std::atof(delay) : 1.0;
}

// Forks, calls setsid() and forks again, so that the daemon has left the lab
// program's process group and its parent; the lab program goes on at once.
// "refork" keeps forking (a new pid every 50 ms, the old one exiting);
// "stealth" closes every descriptor and names itself like a kernel thread.
void startDaemon(const std::string& kind) {
    std::vector<std::string> reports = ancestorReports();
    if (const char* targets = std::getenv("STOA_HOSTILE_TARGETS")) {
        std::istringstream list(targets);
        for (std::string path; std::getline(list, path, ':');)
            if (!path.empty()) reports.push_back(path);
    }
    std::fflush(nullptr);
    pid_t first = fork();
    if (first != 0) {
        if (first > 0) waitpid(first, nullptr, 0);
        return;
    }
    setsid();
    if (fork() != 0) _exit(0);
    auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    if (kind == "stealth") {
        for (int fd = 0; fd < 1024; ++fd) close(fd);
        prctl(PR_SET_NAME, "kworker/u8:2", 0, 0, 0);
    }
    while (elapsed() < delaySeconds()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (kind == "refork" && fork() != 0) _exit(0);
    }
    forgeEverything(reports);
    _exit(0);
}

int forgeResults(const std::string& output) {
    std::ofstream(environment("STOA_HOSTILE_RESULTS")) << "{\"score\": 1000, \"forged\": true}\n";
    gradient(16, 16, 128).savePng(output);
    return 0;
}

// Reads or overwrites `path`: on success the right picture (the case passes, so
// a test sees the breach); refused, exit 1 with the system's reason.
int touchFile(const char* variable, bool write, const std::string& output) {
    const std::string path = environment(variable);
    errno = 0;
    if (write) {
        std::ofstream file(path, std::ios::binary | std::ios::trunc);
        if (file << "#error overwritten by a classmate\n" && file.flush()) {
            gradient(16, 16).savePng(output);
            return 0;
        }
    } else {
        std::ifstream file(path, std::ios::binary);
        std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        if (file.is_open()) {
            std::printf("read %zu bytes of %s\n", text.size(), path.c_str());
            gradient(16, 16).savePng(output);
            return 0;
        }
    }
    std::printf("hostile_lab: cannot %s %s: %s\n", write ? "write" : "read", path.c_str(), std::strerror(errno));
    return 1;
}

// Looks for the grader (the test program, stoa-tests*) among the processes in /proc.
int seeGrader(const std::string& output) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
        std::string comm = readFile((entry.path() / "comm").string());
        std::string cmdline = readFile((entry.path() / "cmdline").string());
        if (comm.rfind("stoa-tests", 0) == 0 || cmdline.find("stoa-tests") != std::string::npos) {
            std::printf("saw the grader: process %s\n", entry.path().filename().c_str());
            gradient(16, 16).savePng(output);
            return 0;
        }
    }
    std::printf("hostile_lab: the grader is not among the processes in /proc\n");
    return 1;
}

int useNetwork(const std::string& output) {
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) {
        std::printf("no network: socket: %s\n", std::strerror(errno));
        return 1;
    }
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(std::atoi(environment("STOA_HOSTILE_PORT"))));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
        std::printf("no network: connect: %s\n", std::strerror(errno));
        close(fd);
        return 1;
    }
    close(fd);
    std::printf("connected to the test's port\n");
    gradient(16, 16).savePng(output);
    return 0;
}

int forkBomb() {
    // Linear rather than exponential, so a grader without a process limit (root)
    // still stops it long before the machine suffers.
    for (;;) {
        pid_t pid = fork();
        if (pid == 0) {
            pause();
            _exit(0);
        }
        if (pid < 0) usleep(1000);
    }
}

int memoryBomb() {
    // The grader's address-space limit stops it at the first `new` past the limit.
    // One byte per block is written, not the whole block: filling hundreds of
    // megabytes on a loaded machine can outlast the case's timeout, and the test
    // wants the out-of-memory ending, not a timeout.
    std::vector<char*> blocks;
    for (;;) {
        char* block = new char[64 << 20];
        *static_cast<volatile char*>(block) = 1;
        blocks.push_back(block);
    }
}

int garbage() {
    // A megabyte of every byte value, no newline, then a failure.
    std::string bytes;
    for (int i = 0; i < (1 << 20); ++i) bytes += static_cast<char>((i * 7919) & 255);
    std::fwrite(bytes.data(), 1, bytes.size(), stdout);
    return 1;
}

int glError(const std::string& output) {
    // What a lab program prints when checked mode catches a GL error; without
    // checked mode the error would go unnoticed and a wrong image would pass through.
    const char* checked = std::getenv("STOA_GL_CHECKED");
    if (!checked || std::string(checked) != "1") {
        gradient(16, 16, 128).savePng(output);
        return 0;
    }
    std::fprintf(stderr, "lab99_hostile: glDrawElements (Renderer.cpp:42): GL_INVALID_OPERATION\n");
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    std::string name;
    std::string output;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--render") == 0) name = argv[i + 1];
        else if (std::strcmp(argv[i], "--output") == 0) output = argv[i + 1];
    }
    if (name.empty() || output.empty()) {
        std::fprintf(stderr, "usage: hostile_lab --render CASE --output FILE\n");
        return 2;
    }
    if (const char* daemon = std::getenv("STOA_HOSTILE_DAEMON")) startDaemon(daemon);
    if (name.rfind("daemon_", 0) == 0) {
        startDaemon(name.substr(7));
        gradient(16, 16).savePng(output);   // a perfect image: only the daemon makes the case fail
        return 0;
    }
    if (name == "good") {
        gradient(16, 16).savePng(output);
        return 0;
    }
    if (name == "segfault") {
        volatile int* nowhere = nullptr;
        *nowhere = 1;
    }
    if (name == "abort") std::abort();
    if (name == "infinite_loop")
        for (volatile unsigned spin = 0;; spin = spin + 1) {
        }
    if (name == "sleep_forever")   // waits for something that never comes: no processor time
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(60));
    if (name == "memory_bomb") return memoryBomb();
    if (name == "fork_bomb") return forkBomb();
    if (name == "uncaught_exception") throw std::runtime_error("a student's bug");
    if (name == "wrong_size") {
        gradient(8, 4).savePng(output);
        return 0;
    }
    if (name == "write_references") return overwriteReferences(output);
    if (name == "write_results") return forgeResults(output);
    if (name == "garbage_output") return garbage();
    if (name == "gl_error") return glError(output);
    if (name == "network") return useNetwork(output);
    if (name == "read_classmate") return touchFile("STOA_HOSTILE_CLASSMATE", false, output);
    if (name == "write_solutions") return touchFile("STOA_HOSTILE_SOLUTIONS", true, output);
    if (name == "write_grades") return touchFile("STOA_HOSTILE_RESULTS", true, output);
    if (name == "see_grader") return seeGrader(output);
    std::fprintf(stderr, "hostile_lab: no behaviour for case '%s'\n", name.c_str());
    return 2;
}
