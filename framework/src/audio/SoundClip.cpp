#include <stoa/audio/SoundClip.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

// The code of stb_vorbis is in a library (Debian's libstb) or in
// StbImplementation.cpp (where stb is headers only: vcpkg, Homebrew); here the
// file only declares it. Debian names it stb_vorbis.h, stb itself stb_vorbis.c.
#define STB_VORBIS_HEADER_ONLY
#if __has_include(<stb_vorbis.h>)
#include <stb_vorbis.h>
#else
#include <stb_vorbis.c>
#endif

#include <array>
#include <cmath>
#include <cstring>
#include <memory>

namespace stoa {

namespace {

std::uint32_t readLe32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
std::uint16_t readLe16(const std::uint8_t* p) { return std::uint16_t(p[0] | p[1] << 8); }

void checkFormat(const std::string& name, int channels, int sampleRate) {
    if (channels < 1 || channels > 2) {
        throw InputError(name, 0, "the sound has " + std::to_string(channels) +
                                      " channels; expected 1 (mono) or 2 (stereo)");
    }
    if (sampleRate < SoundClip::minSampleRate || sampleRate > SoundClip::maxSampleRate) {
        throw InputError(name, 0, "the sample rate is " + std::to_string(sampleRate) + " Hz; expected " +
                                      std::to_string(SoundClip::minSampleRate) + " to " +
                                      std::to_string(SoundClip::maxSampleRate) + " Hz");
    }
}

std::size_t maxFrames(int sampleRate) { return std::size_t(SoundClip::maxSeconds * sampleRate); }

// Ogg's page checksum: CRC-32 with polynomial 0x04c11db7, not reflected,
// starting at 0, over the page with its checksum field read as zero (RFC 3533).
std::uint32_t oggCrc(const std::uint8_t* bytes, std::size_t size) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t r = i << 24;
            for (int bit = 0; bit < 8; ++bit) r = (r & 0x80000000u) ? (r << 1) ^ 0x04c11db7u : r << 1;
            t[i] = r;
        }
        return t;
    }();
    std::uint32_t crc = 0;
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint8_t byte = (i >= 22 && i < 26) ? 0 : bytes[i];   // bytes 22..25 hold the checksum
        crc = (crc << 8) ^ table[((crc >> 24) ^ byte) & 0xFF];
    }
    return crc;
}

// Walks every page before stb_vorbis decodes: stb_vorbis trusts what it reads,
// and a damaged or cut file must be an InputError, not a crash or noise.
void checkOggPages(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    std::size_t at = 0;
    for (int page = 1; at < size; ++page) {
        const std::string where = "Ogg page " + std::to_string(page) + " (byte " + std::to_string(at) + ")";
        if (size - at < 27) throw InputError(name, 0, where + " is cut short: the file is truncated");
        if (std::memcmp(bytes + at, "OggS", 4) != 0) {
            throw InputError(name, 0, where + " does not start with 'OggS': the file is damaged");
        }
        if (bytes[at + 4] != 0) throw InputError(name, 0, where + " has an unknown Ogg version");
        const std::size_t segments = bytes[at + 26];
        if (size - at < 27 + segments) throw InputError(name, 0, where + " is cut short: the file is truncated");
        std::size_t body = 0;
        for (std::size_t i = 0; i < segments; ++i) body += bytes[at + 27 + i];
        const std::size_t pageSize = 27 + segments + body;
        if (size - at < pageSize) throw InputError(name, 0, where + " is cut short: the file is truncated");
        if (oggCrc(bytes + at, pageSize) != readLe32(bytes + at + 22)) {
            throw InputError(name, 0, where + " fails its checksum: the file is damaged");
        }
        if (page == 1 && (body < 7 || std::memcmp(bytes + at + 27 + segments, "\x01vorbis", 7) != 0)) {
            throw InputError(name, 0, "an Ogg file, but its first stream is not Vorbis audio "
                                      "(Opus and FLAC in Ogg are not read; expected Ogg Vorbis)");
        }
        at += pageSize;
    }
}

std::string describeVorbisError(int error) {
    switch (error) {
    case VORBIS_outofmem: return "out of memory";
    case VORBIS_unexpected_eof: return "the stream ends early";
    case VORBIS_invalid_setup: case VORBIS_invalid_first_page: case VORBIS_bad_packet_type:
    case VORBIS_invalid_stream: case VORBIS_cant_find_last_page: return "the Vorbis headers are invalid";
    case VORBIS_too_many_channels: return "it has more channels than stb_vorbis decodes";
    case VORBIS_invalid_stream_structure_version: return "an unknown Vorbis version";
    case VORBIS_feature_not_supported: return "it uses a Vorbis feature stb_vorbis does not support";
    default: return "stb_vorbis error " + std::to_string(error);
    }
}

SoundClip decodeOgg(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    checkOggPages(bytes, size, name);
    // stb_vorbis sizes its tables from the stream's setup header, which a bit flip
    // (with the checksums fixed) can make ask for gigabytes; given a buffer of its
    // own, it takes every table from there and fails at once when it would not fit.
    std::vector<char> arena(SoundClip::maxDecoderBytes);
    const stb_vorbis_alloc alloc{arena.data(), static_cast<int>(arena.size())};
    int error = 0;
    std::unique_ptr<stb_vorbis, void (*)(stb_vorbis*)> vorbis(stb_vorbis_open_memory(bytes, int(size), &error, &alloc),
                                                              stb_vorbis_close);
    if (!vorbis && error == VORBIS_outofmem)
        throw InputError(name, 0, "cannot decode the Ogg Vorbis stream: its setup header asks for more than " +
                                      std::to_string(SoundClip::maxDecoderBytes >> 20) +
                                      " MiB of decoder tables, which no sound clip needs: the stream is corrupt");
    if (!vorbis) throw InputError(name, 0, "cannot decode the Ogg Vorbis stream: " + describeVorbisError(error));
    const stb_vorbis_info info = stb_vorbis_get_info(vorbis.get());
    checkFormat(name, info.channels, int(info.sample_rate));

    const int channels = info.channels;
    const std::size_t limit = maxFrames(int(info.sample_rate));
    // The length the last page declares, before anything is decoded.
    const std::size_t declared = stb_vorbis_stream_length_in_samples(vorbis.get());
    if (declared > limit) {
        throw InputError(name, 0, "the sound is longer than " + std::to_string(int(SoundClip::maxSeconds)) +
                                      " seconds (its last page says " + std::to_string(declared) +
                                      " samples); expected a short clip");
    }
    std::vector<std::int16_t> samples;
    std::vector<short> block(4096 * std::size_t(channels));
    for (;;) {
        const int frames = stb_vorbis_get_samples_short_interleaved(vorbis.get(), channels, block.data(), int(block.size()));
        if (frames <= 0) break;
        samples.insert(samples.end(), block.begin(), block.begin() + std::ptrdiff_t(frames) * channels);
        if (samples.size() / channels > limit) {
            throw InputError(name, 0, "the sound is longer than " + std::to_string(int(SoundClip::maxSeconds)) +
                                          " seconds; expected a short clip");
        }
    }
    if (samples.empty()) throw InputError(name, 0, "the Ogg Vorbis stream holds no samples");
    return SoundClip(std::move(samples), channels, int(info.sample_rate), name);
}

// RIFF WAVE: a 12-byte header, then chunks (a 4-byte id, a 4-byte size, the
// data, padded to an even size). "fmt " says how samples are stored, "data"
// holds them; other chunks (LIST, fact, ...) are skipped.
SoundClip decodeWav(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    int formatTag = 0, channels = 0, sampleRate = 0, bits = 0, blockAlign = 0;
    bool haveFormat = false;
    std::size_t at = 12;
    while (at < size) {
        if (size - at < 8) throw InputError(name, 0, "a chunk header at byte " + std::to_string(at) + " is cut short");
        const std::string id(reinterpret_cast<const char*>(bytes + at), 4);
        const std::size_t chunkSize = readLe32(bytes + at + 4);
        const std::uint8_t* data = bytes + at + 8;
        const std::size_t available = size - at - 8;
        if (id == "fmt ") {
            if (chunkSize < 16 || chunkSize > available) {
                throw InputError(name, 0, "the 'fmt ' chunk is " + std::to_string(chunkSize) +
                                              " bytes; expected at least 16, within the file");
            }
            formatTag = readLe16(data);
            channels = readLe16(data + 2);
            sampleRate = int(readLe32(data + 4));
            blockAlign = readLe16(data + 12);
            bits = readLe16(data + 14);
            if (formatTag == 0xFFFE) {   // WAVE_FORMAT_EXTENSIBLE: the real format is the sub-format GUID's first two bytes
                if (chunkSize < 40) throw InputError(name, 0, "the extensible 'fmt ' chunk is shorter than 40 bytes");
                formatTag = readLe16(data + 24);
            }
            haveFormat = true;
        } else if (id == "data") {
            if (!haveFormat) throw InputError(name, 0, "the 'data' chunk comes before any 'fmt ' chunk");
            if (formatTag != 1) {
                throw InputError(name, 0, "the samples are stored in format " + std::to_string(formatTag) +
                                              "; expected uncompressed PCM (1)");
            }
            if (bits != 8 && bits != 16) {
                throw InputError(name, 0, std::to_string(bits) + "-bit samples; expected 8 or 16 bits");
            }
            checkFormat(name, channels, sampleRate);
            if (blockAlign != channels * bits / 8) {
                throw InputError(name, 0, "the block size is " + std::to_string(blockAlign) + " bytes; expected " +
                                              std::to_string(channels * bits / 8) + " for " +
                                              std::to_string(channels) + " channels of " + std::to_string(bits) + " bits");
            }
            if (chunkSize > available) {
                throw InputError(name, 0, "the 'data' chunk claims " + std::to_string(chunkSize) + " bytes but " +
                                              std::to_string(available) + " follow (the file is cut short, "
                                              "or its writer never finished the header)");
            }
            const std::size_t frames = chunkSize / std::size_t(blockAlign);
            if (frames == 0) throw InputError(name, 0, "the 'data' chunk holds no samples");
            if (frames > maxFrames(sampleRate)) {
                throw InputError(name, 0, "the sound is longer than " + std::to_string(int(SoundClip::maxSeconds)) +
                                              " seconds; expected a short clip");
            }
            std::vector<std::int16_t> samples(frames * std::size_t(channels));
            for (std::size_t i = 0; i < samples.size(); ++i) {
                samples[i] = bits == 16 ? std::int16_t(readLe16(data + 2 * i))
                                        : std::int16_t((int(data[i]) - 128) * 256);   // 8-bit WAV is unsigned
            }
            return SoundClip(std::move(samples), channels, sampleRate, name);
        }
        if (chunkSize > available) {
            throw InputError(name, 0, "the '" + id + "' chunk claims " + std::to_string(chunkSize) +
                                          " bytes but the file ends first");
        }
        at += 8 + chunkSize + (chunkSize & 1);
    }
    throw InputError(name, 0, haveFormat ? "the WAV file has no 'data' chunk" : "the WAV file has no 'fmt ' chunk");
}

} // namespace

SoundClip::SoundClip(std::vector<std::int16_t> samples, int channels, int sampleRate, std::string name)
    : m_samples(std::move(samples)), m_channels(channels), m_sampleRate(sampleRate), m_name(std::move(name)) {
    STOA_ASSERT(channels == 1 || channels == 2, "SoundClip: channels must be 1 (mono) or 2 (stereo interleaved).");
    STOA_ASSERT(sampleRate >= minSampleRate && sampleRate <= maxSampleRate,
                "SoundClip: the sample rate must be within [minSampleRate, maxSampleRate] hertz.");
    STOA_ASSERT(m_samples.size() % std::size_t(channels) == 0,
                "SoundClip: a stereo clip needs a whole number of frames (an even sample count).");
}

SoundClip SoundClip::fromFile(const std::filesystem::path& path) {
    const std::string bytes = readInputFile(path, maxFileBytes, "a sound file (Ogg Vorbis or WAV)");
    return decode(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), path.string());
}

SoundClip SoundClip::decode(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    if (size >= 4 && std::memcmp(bytes, "OggS", 4) == 0) return decodeOgg(bytes, size, name);
    if (size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WAVE", 4) == 0) {
        return decodeWav(bytes, size, name);
    }
    if (size == 0) throw InputError(name, 0, "the file is empty; expected Ogg Vorbis or WAV");
    throw InputError(name, 0, "not a sound file Stoa reads: expected Ogg Vorbis (starting 'OggS') "
                              "or WAV (starting 'RIFF', then 'WAVE')");
}

double SoundClip::rms(int channel) const {
    STOA_ASSERT(channel >= 0 && channel < m_channels, "SoundClip::rms(): the channel must be 0 or, for stereo, 1.");
    const std::size_t frames = frameCount();
    if (frames == 0) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < frames; ++i) {
        const double s = m_samples[i * m_channels + channel] / 32768.0;
        sum += s * s;
    }
    return std::sqrt(sum / double(frames));
}

SoundClip SoundClip::mono() const {
    if (m_channels == 1) return *this;
    std::vector<std::int16_t> mixed(frameCount());
    for (std::size_t i = 0; i < mixed.size(); ++i) {
        mixed[i] = std::int16_t((int(m_samples[2 * i]) + int(m_samples[2 * i + 1])) / 2);
    }
    return SoundClip(std::move(mixed), 1, m_sampleRate, m_name);
}

} // namespace stoa
