// SoundDevice without a sound card. OpenAL Soft's "wave" backend mixes in
// real time into a WAV file, so a test can hear where a sound was placed: a
// source to the listener's right must be louder in the right channel. The
// "null" backend plays to nothing; an unknown driver leaves no device, and
// sound must turn off quietly.
//
// OpenAL Soft reads its configuration (ALSOFT_CONF and the files it names)
// once per process, when the first device opens. So every test here opens its
// device in a child process (fork) with the configuration it needs; the child
// reports back through files, and the parent checks them.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/audio/SoundDevice.hpp>
#include <stoa/core/InputError.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace stoa;
namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

/// What a child process did: its exit status, its stderr, and the
/// "key value" lines it wrote to its report.
struct ChildRun {
    bool exited = false;     // false: killed (a crash, an abort, or the time limit)
    int exitCode = -1;
    std::string stderrText;
    std::map<std::string, std::string> report;
};

/// Runs `body` in a child process with ALSOFT_CONF naming a file that holds
/// `config`, in `folder`. `body` writes what it saw with report(key, value).
/// The child gets 10 seconds; then it is killed.
ChildRun runWithOpenAlConfig(const test::TempFolder& folder, const std::string& config,
                             const std::function<void(const std::function<void(std::string, std::string)>&)>& body) {
    const fs::path configPath = folder.write("alsoft.conf", config);
    const fs::path reportPath = folder / "report.txt", stderrPath = folder / "stderr.txt";
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        // Catch's own signal handlers would report a crash here as the parent's failure.
        for (int signalNumber : {SIGABRT, SIGSEGV, SIGFPE, SIGILL, SIGBUS, SIGTERM}) signal(signalNumber, SIG_DFL);
        const int errors = ::open(stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(errors, 2);
        const int nothing = ::open("/dev/null", O_WRONLY);
        ::dup2(nothing, 1);
        setenv("ALSOFT_CONF", configPath.c_str(), 1);
        unsetenv("ALSOFT_DRIVERS");   // it would override the config's drivers
        int status = 0;
        try {
            std::ofstream report(reportPath);
            body([&](std::string key, std::string value) { report << key << ' ' << value << '\n' << std::flush; });
        } catch (const std::exception& error) {
            std::fprintf(stderr, "exception: %s\n", error.what());
            status = 3;
        }
        std::fflush(stderr);
        _exit(status);   // not exit(): the parent's Catch must not run its teardown here
    }
    ChildRun run;
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    run.exited = WIFEXITED(status);
    run.exitCode = run.exited ? WEXITSTATUS(status) : -1;
    run.stderrText = readText(stderrPath);
    std::istringstream lines(readText(reportPath));
    std::string key, value;
    while (lines >> key && std::getline(lines >> std::ws, value)) run.report[key] = value;
    return run;
}

/// One second of a sine tone, mono, 44100 Hz.
SoundClip tone(double hertz, double amplitude) {
    std::vector<std::int16_t> samples(44100);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        samples[i] = std::int16_t(std::lround(amplitude * 32767.0 * std::sin(2.0 * M_PI * hertz * double(i) / 44100.0)));
    }
    return SoundClip(std::move(samples), 1, 44100, "tone");
}

/// A config for the wave backend writing 16-bit stereo at 44100 Hz into `wav`,
/// with plain amplitude panning (no HRTF), so left and right are the speakers'.
std::string waveConfig(const fs::path& wav) {
    return "[general]\ndrivers = wave\nchannels = stereo\nsample-type = int16\nfrequency = 44100\n"
           "hrtf = false\nstereo-mode = speakers\nstereo-encoding = panpot\n[wave]\nfile = " +
           wav.string() + "\n";
}

/// Plays a looping tone at `positionWorld` for 0.3 s (the wave backend runs in
/// real time), listener at the origin looking down -z, and closes the device.
void playToneAt(const fs::path& wav, const test::TempFolder& folder, glm::vec3 positionWorld, bool muted,
                ChildRun& run) {
    run = runWithOpenAlConfig(folder, waveConfig(wav), [&](const auto& report) {
        SoundDevice sound;
        report("enabled", std::to_string(sound.enabled()));
        report("device", sound.deviceName());
        sound.setListener(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        sound.setMuted(muted);
        const SoundHandle playing = sound.play(sound.upload(tone(440.0, 0.5)), positionWorld, 1.0f, true);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        report("playing", std::to_string(sound.playing(playing)));
    });   // the device closes here, which finishes the WAV header
}

} // namespace

TEST_CASE("A sound to the listener's right is louder in the right channel and one to the left in the left",
          "[audio][device]") {
    struct Side {
        const char* name;
        float x;
        int louder;   // channel: 0 left, 1 right
    };
    for (const Side& side : {Side{"right (+x)", 2.0f, 1}, Side{"left (-x)", -2.0f, 0}}) {
        INFO("source at the " << side.name);
        test::TempFolder folder("sound-wave");
        const fs::path wav = folder / "out.wav";
        ChildRun run;
        playToneAt(wav, folder, glm::vec3(side.x, 0.0f, 0.0f), false, run);
        INFO("child stderr: " << run.stderrText);
        REQUIRE(run.exited);
        REQUIRE(run.exitCode == 0);
        CHECK(run.report["enabled"] == "1");
        CHECK(run.report["playing"] == "1");

        // SoundClip reads the WAVE_FORMAT_EXTENSIBLE file the wave backend
        // writes; a data size the device never finished would be an error.
        const SoundClip heard = SoundClip::fromFile(wav);
        REQUIRE(heard.channels() == 2);
        CHECK(heard.sampleRate() == 44100);
        CHECK(heard.durationSeconds() > 0.15);
        const double near = heard.rms(side.louder), far = heard.rms(1 - side.louder);
        INFO("RMS near " << near << ", far " << far);
        CHECK(near > 0.01);
        CHECK(near > 1.5 * far);
    }
}

TEST_CASE("Muting silences the output while the sound goes on playing", "[audio][device]") {
    test::TempFolder folder("sound-mute");
    const fs::path wav = folder / "out.wav";
    ChildRun run;
    playToneAt(wav, folder, glm::vec3(2.0f, 0.0f, 0.0f), true, run);
    INFO("child stderr: " << run.stderrText);
    REQUIRE(run.exitCode == 0);
    CHECK(run.report["playing"] == "1");
    const SoundClip heard = SoundClip::fromFile(wav);
    CHECK(heard.durationSeconds() > 0.15);
    CHECK(heard.rms(0) < 1e-4);
    CHECK(heard.rms(1) < 1e-4);
}

TEST_CASE("On the null device every call works: one-shots end and free their source and old handles go stale",
          "[audio][device]") {
    test::TempFolder folder("sound-null");
    const ChildRun run = runWithOpenAlConfig(folder, "[general]\ndrivers = null\n", [](const auto& report) {
        SoundDevice sound;
        report("enabled", std::to_string(sound.enabled()));
        const SoundBuffer blip = sound.upload(SoundClip(std::vector<std::int16_t>(441, 1000), 1, 44100, "blip"));
        const SoundBuffer wind = sound.upload(tone(200.0, 0.2));
        const SoundBuffer stereo = sound.upload(SoundClip(std::vector<std::int16_t>(882, 500), 2, 44100, "stereo"));
        sound.setListener(glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        const SoundHandle ambient = sound.playAmbient(stereo, 0.5f);
        const SoundHandle loop = sound.play(wind, glm::vec3(5.0f, 0.0f, 0.0f), 0.8f, true);
        const SoundHandle once = sound.play(blip, glm::vec3(0.0f), 1.0f);
        report("handles", std::to_string(bool(ambient) && bool(loop) && bool(once)));
        report("inUse", std::to_string(sound.sourcesInUse()));
        sound.setPosition(loop, glm::vec3(-5.0f, 0.0f, 0.0f));
        sound.setGain(loop, 0.3f);
        sound.setMuted(true);
        report("muted", std::to_string(sound.muted()));
        sound.setMuted(false);
        std::this_thread::sleep_for(std::chrono::milliseconds(150));   // the 10 ms blip ends
        sound.update();
        report("onceAfter", std::to_string(sound.playing(once)));
        report("loopAfter", std::to_string(sound.playing(loop)));
        report("inUseAfter", std::to_string(sound.sourcesInUse()));
        sound.stop(loop);
        report("loopStopped", std::to_string(sound.playing(loop)));
        // A new sound reuses a freed source; the old handles must not reach it.
        const SoundHandle next = sound.play(blip, glm::vec3(0.0f), 1.0f, true);
        sound.stop(once);
        sound.stop(loop);
        sound.setPosition(once, glm::vec3(9.0f));
        report("nextPlaying", std::to_string(sound.playing(next)));
        report("inUseEnd", std::to_string(sound.sourcesInUse()));
        sound.stop(SoundHandle{});
        sound.stop(SoundHandle{0xFFFFFFFFu});
    });
    INFO("child stderr: " << run.stderrText);
    REQUIRE(run.exitCode == 0);
    CHECK(run.report.at("enabled") == "1");
    CHECK(run.report.at("handles") == "1");
    CHECK(run.report.at("inUse") == "3");
    CHECK(run.report.at("muted") == "1");
    CHECK(run.report.at("onceAfter") == "0");
    CHECK(run.report.at("loopAfter") == "1");
    CHECK(run.report.at("inUseAfter") == "2");
    CHECK(run.report.at("loopStopped") == "0");
    CHECK(run.report.at("nextPlaying") == "1");
    CHECK(run.report.at("inUseEnd") == "2");
    CHECK(run.stderrText.empty());
}

TEST_CASE("A device that cannot open turns sound off with one line and no exception", "[audio][device]") {
    test::TempFolder folder("sound-off");
    const ChildRun run = runWithOpenAlConfig(folder, "[general]\ndrivers = no-such-driver\n", [](const auto& report) {
        SoundDevice sound;
        report("enabled", std::to_string(sound.enabled()));
        report("reason", sound.offReason());
        const SoundBuffer step = sound.upload(SoundClip(std::vector<std::int16_t>(100, 1000), 1, 44100, "step"));
        sound.setListener(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        const SoundHandle playing = sound.play(step, glm::vec3(1.0f, 0.0f, 0.0f));
        sound.setPosition(playing, glm::vec3(2.0f));
        sound.setMuted(true);
        sound.update();
        sound.stop(playing);
        report("handle", std::to_string(playing.id));
        report("playing", std::to_string(sound.playing(playing)));
        report("muted", std::to_string(sound.muted()));
    });
    INFO("child stderr: " << run.stderrText);
    REQUIRE(run.exitCode == 0);
    CHECK(run.report.at("enabled") == "0");
    CHECK(run.report.at("reason").find("no audio device") != std::string::npos);
    CHECK(run.report.at("handle") == "0");
    CHECK(run.report.at("playing") == "0");
    CHECK(run.report.at("muted") == "1");
    // Exactly one line, ours: no ALSA or OpenAL Soft noise.
    CHECK(run.stderrText.rfind("sound: off (no audio device: ", 0) == 0);
    CHECK(std::count(run.stderrText.begin(), run.stderrText.end(), '\n') == 1);
}

TEST_CASE("Playing a stereo buffer in the world stops with a message saying what to do", "[audio][device]") {
    test::TempFolder folder("sound-stereo");
    const ChildRun run = runWithOpenAlConfig(folder, "[general]\ndrivers = null\n", [](const auto&) {
        SoundDevice sound = SoundDevice::off("testing");   // the assertion holds with sound off too
        const SoundBuffer stereo = sound.upload(SoundClip(std::vector<std::int16_t>(20, 1), 2, 44100, "stereo"));
        sound.playAmbient(stereo);   // fine: not placed
        sound.play(stereo, glm::vec3(1.0f, 0.0f, 0.0f));
    });
    CHECK_FALSE(run.exited);   // abort()
    INFO(run.stderrText);
    CHECK(run.stderrText.find("sound: off (testing)") != std::string::npos);
    CHECK(run.stderrText.find("SoundDevice::play(): the buffer is stereo") != std::string::npos);
    CHECK(run.stderrText.find("clip.mono()") != std::string::npos);
}
