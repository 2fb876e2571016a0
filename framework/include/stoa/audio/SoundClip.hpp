#pragma once
// A decoded sound in memory: signed 16-bit samples, mono or stereo
// (interleaved left, right), at a sample rate in hertz. Needs no sound card
// and no OpenAL; SoundDevice (stoa/audio/SoundDevice.hpp) plays it.
//
//   SoundClip step = SoundClip::fromFile(paths::assetsDir() / "sounds/footstep.ogg");
//   step.durationSeconds();   // 0.3
//
// Only a mono clip can be placed in the world: OpenAL plays stereo as it is,
// without positioning. mono() mixes a stereo clip down.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace stoa {

class SoundClip {
public:
    /// Limits every sound file must keep (fromFile, decode).
    static constexpr std::size_t maxFileBytes = 64u << 20;   // 64 MiB read at most
    static constexpr double maxSeconds = 600.0;              // 10 minutes decoded at most
    static constexpr int minSampleRate = 8000;               // hertz
    static constexpr int maxSampleRate = 192000;
    /// All the memory stb_vorbis may take for an Ogg stream's decoder (its
    /// tables and buffers); the shipped clips need under 1 MiB.
    static constexpr std::size_t maxDecoderBytes = 4u << 20;

    SoundClip() = default;
    /// `samples` interleaved, channels 1 or 2, a whole number of frames;
    /// minSampleRate <= sampleRate <= maxSampleRate. `name` appears in messages.
    SoundClip(std::vector<std::int16_t> samples, int channels, int sampleRate, std::string name = {});

    /// Loads Ogg Vorbis (.ogg, decoded by stb_vorbis) or uncompressed PCM WAV
    /// (8 or 16 bits, WAVE_FORMAT_PCM or WAVE_FORMAT_EXTENSIBLE with a PCM
    /// sub-format), mono or stereo; the format comes from the first bytes,
    /// not the name. Every Ogg page's checksum is verified before stb_vorbis
    /// sees a byte, and a WAV's chunks must fit in the file. Throws
    /// InputError naming the file and what was expected: a missing file, a
    /// truncated or damaged one, another format, more than two channels, a
    /// rate outside [minSampleRate, maxSampleRate], over maxSeconds.
    static SoundClip fromFile(const std::filesystem::path& path);
    /// The same for a file already in memory; `name` is the file named in errors.
    static SoundClip decode(const std::uint8_t* bytes, std::size_t size, const std::string& name);

    int channels() const { return m_channels; }        // 1 (mono) or 2 (stereo)
    int sampleRate() const { return m_sampleRate; }    // frames per second
    std::size_t frameCount() const { return m_channels ? m_samples.size() / m_channels : 0; }
    double durationSeconds() const { return m_sampleRate ? double(frameCount()) / m_sampleRate : 0.0; }
    bool empty() const { return m_samples.empty(); }
    const std::string& name() const { return m_name; }
    /// Interleaved samples: frameCount() * channels() of them.
    const std::vector<std::int16_t>& samples() const { return m_samples; }

    /// Root mean square of channel `channel` (0 = left or mono, 1 = right),
    /// in [0, 1] of full scale. 0 for an empty clip.
    double rms(int channel = 0) const;
    /// This clip as mono: a stereo clip's channels averaged; a mono clip as it is.
    SoundClip mono() const;

private:
    std::vector<std::int16_t> m_samples;
    int m_channels = 1;
    int m_sampleRate = 44100;
    std::string m_name;
};

} // namespace stoa
