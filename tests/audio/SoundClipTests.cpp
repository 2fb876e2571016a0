// SoundClip: decoding Ogg Vorbis and WAV, and every broken file named in an
// InputError that says what was expected.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/audio/SoundClip.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace stoa;
namespace fs = std::filesystem;

// Checks that `text` holds every one of the strings that follow, and shows it when not.
#define CHECK_MENTIONS(text, ...)                                              \
    do {                                                                       \
        const std::string checkedText = (text);                                \
        INFO(checkedText);                                                     \
        for (const char* part : {__VA_ARGS__}) CHECK(checkedText.find(part) != std::string::npos); \
    } while (false)

namespace {

const fs::path soundsDir = paths::assetsDir() / "sounds";

std::string readBytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

void put16(std::string& out, unsigned value) { out += char(value & 0xFF), out += char(value >> 8 & 0xFF); }
void put32(std::string& out, std::uint32_t value) { put16(out, value & 0xFFFF), put16(out, value >> 16); }

struct WavFormat {
    int formatTag = 1;     // 1 PCM, 3 float, 0xFFFE extensible
    int channels = 1;
    int rate = 22050;
    int bits = 16;
    int subFormat = 1;     // the extensible format's sub-format
};

/// A WAV file: RIFF header, "fmt " (16 or 40 bytes), "data" with `data`.
/// `dataSizeOverride` >= 0 writes that size in the data chunk's header instead.
std::string wavFile(const WavFormat& f, const std::string& data, long dataSizeOverride = -1) {
    std::string fmt;
    put16(fmt, unsigned(f.formatTag));
    put16(fmt, unsigned(f.channels));
    put32(fmt, std::uint32_t(f.rate));
    put32(fmt, std::uint32_t(f.rate * f.channels * f.bits / 8));
    put16(fmt, unsigned(f.channels * f.bits / 8));
    put16(fmt, unsigned(f.bits));
    if (f.formatTag == 0xFFFE) {
        put16(fmt, 22);
        put16(fmt, unsigned(f.bits));
        put32(fmt, f.channels == 1 ? 0x4 : 0x3);
        put16(fmt, unsigned(f.subFormat));
        fmt += std::string("\x00\x00\x00\x00\x10\x00\x80\x00\x00\xaa\x00\x38\x9b\x71", 14);
    }
    std::string body = "WAVE";
    body += "fmt ";
    put32(body, std::uint32_t(fmt.size()));
    body += fmt;
    body += "LIST";   // a chunk the reader skips
    put32(body, 4);
    body += "INFO";
    body += "data";
    put32(body, std::uint32_t(dataSizeOverride >= 0 ? dataSizeOverride : long(data.size())));
    body += data;
    std::string out = "RIFF";
    put32(out, std::uint32_t(body.size()));
    return out + body;
}

std::string decodeError(const std::string& bytes, const std::string& name) {
    try {
        SoundClip::decode(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), name);
    } catch (const InputError& error) {
        CHECK(error.file() == name);
        return error.what();
    }
    FAIL("no InputError for " << name);
    return {};
}

} // namespace

TEST_CASE("The committed sounds decode to the promised clips", "[audio]") {
    struct Expected {
        const char* file;
        double seconds;
    };
    for (const Expected& expected : {Expected{"footstep.ogg", 0.30}, Expected{"spark.ogg", 0.45},
                                     Expected{"ambient_wind.ogg", 4.0}}) {
        INFO(expected.file);
        const SoundClip clip = SoundClip::fromFile(soundsDir / expected.file);
        CHECK(clip.channels() == 1);
        CHECK(clip.sampleRate() == 44100);
        CHECK(clip.frameCount() == std::size_t(expected.seconds * 44100));
        CHECK(clip.rms() > 0.02);                  // not silent
        CHECK(clip.name() == (soundsDir / expected.file).string());
        CHECK(fs::file_size(soundsDir / expected.file) < 60 * 1024);
    }
}

TEST_CASE("A damaged or cut or foreign Ogg file is an InputError naming it", "[audio]") {
    const std::string good = readBytes(soundsDir / "footstep.ogg");
    REQUIRE(good.size() > 1000);

    std::string flipped = good;
    flipped[good.size() / 2] = char(flipped[good.size() / 2] ^ 0x40);
    CHECK_MENTIONS(decodeError(flipped, "flipped.ogg"), "flipped.ogg", "fails its checksum");

    CHECK_MENTIONS(decodeError(good.substr(0, good.size() - 100), "cut.ogg"), "cut.ogg", "truncated");
    CHECK_MENTIONS(decodeError(good.substr(0, 10), "header.ogg"), "truncated");
    CHECK_MENTIONS(decodeError("OggS" + std::string(60, 'x'), "junk.ogg"), "junk.ogg");
    CHECK_MENTIONS(decodeError("ID3\x03 not a sound at all", "song.mp3"), "expected Ogg Vorbis", "WAV");
    CHECK_MENTIONS(decodeError("", "empty.ogg"), "empty");
}

namespace {

// Ogg's page checksum (RFC 3533), to damage a stream the way an attacker would: with the checksums fixed.
std::uint32_t pageCrc(const std::string& page) {
    std::uint32_t crc = 0;
    for (std::size_t i = 0; i < page.size(); ++i) {
        const std::uint8_t byte = (i >= 22 && i < 26) ? 0 : std::uint8_t(page[i]);
        crc ^= std::uint32_t(byte) << 24;
        for (int bit = 0; bit < 8; ++bit) crc = (crc & 0x80000000u) ? (crc << 1) ^ 0x04c11db7u : crc << 1;
    }
    return crc;
}

// Sets the checksum of every page of `bytes` to match its content.
void fixChecksums(std::string& bytes) {
    for (std::size_t at = 0; at + 27 <= bytes.size();) {
        const std::size_t segments = std::uint8_t(bytes[at + 26]);
        std::size_t body = 0;
        for (std::size_t i = 0; i < segments; ++i) body += std::uint8_t(bytes[at + 27 + i]);
        const std::size_t size = 27 + segments + body;
        const std::uint32_t crc = pageCrc(bytes.substr(at, size));
        for (int i = 0; i < 4; ++i) bytes[at + 22 + std::size_t(i)] = char((crc >> (8 * i)) & 0xFF);
        at += size;
    }
}

} // namespace

TEST_CASE("Issue 25: a setup header that asks for huge decoder tables is refused at once, as corrupt", "[audio][issue25]") {
    std::string bytes = readBytes(soundsDir / "spark.ogg");
    // The setup header: "\x05vorbis", the codebook count - 1 (8 bits), then the first codebook:
    // its sync pattern (3 bytes), dimensions (16 bits) and number of entries (24 bits).
    const std::size_t setup = bytes.find("\x05vorbis");
    REQUIRE(setup != std::string::npos);
    const std::size_t entries = setup + 7 + 1 + 3 + 2;
    REQUIRE(bytes.substr(setup + 8, 3) == "BCV");
    for (int i = 0; i < 3; ++i) bytes[entries + std::size_t(i)] = char(0xFF);   // 16,777,215 entries
    fixChecksums(bytes);
    CHECK_MENTIONS(decodeError(bytes, "bomb.ogg"), "bomb.ogg", "setup header asks for more than 4 MiB", "the stream is corrupt");
}

TEST_CASE("A missing sound file is an InputError naming it", "[audio]") {
    const fs::path missing = soundsDir / "no_such_sound.ogg";
    try {
        SoundClip::fromFile(missing);
        FAIL("no error");
    } catch (const InputError& error) {
        CHECK(error.file() == missing.string());
        CHECK_MENTIONS(error.what(), "does not exist");
    }
}

TEST_CASE("PCM WAV files decode: 16-bit mono and 8-bit stereo and extensible", "[audio]") {
    std::string data;
    for (int v : {0, 1000, -1000, 32767, -32768, 7}) put16(data, unsigned(v) & 0xFFFF);
    const std::string mono = wavFile({}, data);
    const SoundClip a = SoundClip::decode(reinterpret_cast<const std::uint8_t*>(mono.data()), mono.size(), "a.wav");
    CHECK(a.channels() == 1);
    CHECK(a.sampleRate() == 22050);
    CHECK(a.samples() == std::vector<std::int16_t>{0, 1000, -1000, 32767, -32768, 7});

    WavFormat stereo8;
    stereo8.channels = 2, stereo8.bits = 8;
    const std::string eight = wavFile(stereo8, std::string("\x80\xff\x00\x80", 4));
    const SoundClip b = SoundClip::decode(reinterpret_cast<const std::uint8_t*>(eight.data()), eight.size(), "b.wav");
    CHECK(b.channels() == 2);
    CHECK(b.frameCount() == 2);
    CHECK(b.samples() == std::vector<std::int16_t>{0, 127 * 256, -128 * 256, 0});
    CHECK(b.mono().samples() == std::vector<std::int16_t>{127 * 128, -128 * 128});

    WavFormat extensible;
    extensible.formatTag = 0xFFFE, extensible.channels = 2;
    test::TempFolder folder("wav");
    const fs::path path = folder.write("c.wav", wavFile(extensible, data.substr(0, 8)));
    const SoundClip c = SoundClip::fromFile(path);
    CHECK(c.channels() == 2);
    CHECK(c.samples() == std::vector<std::int16_t>{0, 1000, -1000, 32767});
    CHECK(c.rms(1) > c.rms(0));
}

TEST_CASE("A broken WAV file is an InputError naming it and what was expected", "[audio]") {
    std::string data;
    for (int i = 0; i < 8; ++i) put16(data, unsigned(i * 100));

    CHECK_MENTIONS(decodeError(wavFile({}, data, 4000), "cut.wav"), "cut.wav", "claims 4000 bytes");
    WavFormat floats;
    floats.formatTag = 3, floats.bits = 32;
    CHECK_MENTIONS(decodeError(wavFile(floats, data), "float.wav"), "expected uncompressed PCM");
    WavFormat extensibleFloat;
    extensibleFloat.formatTag = 0xFFFE, extensibleFloat.subFormat = 3;
    CHECK_MENTIONS(decodeError(wavFile(extensibleFloat, data), "xfloat.wav"), "expected uncompressed PCM");
    WavFormat deep;
    deep.bits = 24;
    CHECK_MENTIONS(decodeError(wavFile(deep, data.substr(0, 15)), "deep.wav"), "expected 8 or 16 bits");
    WavFormat surround;
    surround.channels = 6;
    CHECK_MENTIONS(decodeError(wavFile(surround, data.substr(0, 12)), "six.wav"), "6 channels", "expected 1 (mono) or 2 (stereo)");
    WavFormat slow;
    slow.rate = 100;
    CHECK_MENTIONS(decodeError(wavFile(slow, data), "slow.wav"), "100 Hz");
    CHECK_MENTIONS(decodeError(wavFile({}, ""), "silent.wav"), "no samples");
    CHECK_MENTIONS(decodeError(wavFile({}, data).substr(0, 30), "short.wav"), "short.wav");
    CHECK_MENTIONS(decodeError(std::string("RIFF\x04\x00\x00\x00WAVE", 12), "bare.wav"), "no 'fmt ' chunk");
}
