#include "Sounds.hpp"

#include "Noise.hpp"
#include "PortableMath.hpp"

#include <stoa/core/InputError.hpp>

#include <vorbis/vorbisenc.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace stoa::assets {

namespace {

constexpr int kRate = 44100;
constexpr double kPi = 3.14159265358979323846;

/// White noise in [-1, 1): sample `i` of the stream `seed`.
double noise(std::uint32_t seed, int i) {
    return hash32(hash32(seed) ^ static_cast<std::uint32_t>(i)) / 2147483648.0 - 1.0;
}

/// A one-pole low-pass: each output moves `alpha` of the way to the input.
/// alpha = 1 - exp(-2 pi fc / fs) puts the -3 dB point near fc.
struct LowPass {
    double alpha;
    double state = 0.0;
    explicit LowPass(double cutoffHz) : alpha(1.0 - portableExp(-2.0 * kPi * cutoffHz / kRate)) {}
    double operator()(double x) { return state += alpha * (x - state); }
};

/// Chamberlin's state-variable filter, band-pass output; stable for centres
/// well below fs / 6, which every use here keeps.
struct BandPass {
    double low = 0.0, band = 0.0;
    double operator()(double x, double centreHz, double q) {
        const double f = 2.0 * portableSin(kPi * centreHz / kRate);
        low += f * band;
        const double high = x - low - band / q;
        band += f * high;
        return band;
    }
};

/// Scales `signal` so that its largest magnitude is `peak` (of full scale) and rounds to 16 bits.
SoundClip toClip(const std::vector<double>& signal, double peak, const std::string& name) {
    double largest = 1e-9;
    for (double s : signal) largest = std::max(largest, std::fabs(s));
    std::vector<std::int16_t> samples(signal.size());
    for (std::size_t i = 0; i < signal.size(); ++i) {
        samples[i] = static_cast<std::int16_t>(std::lround(signal[i] / largest * peak * 32767.0));
    }
    return SoundClip(std::move(samples), 1, kRate, name);
}

// A step on stone: the heel (a burst of noise low-passed at 900 Hz, attack
// 2 ms, decay 45 ms) with a thump at 85 Hz, and the toe 60 ms later, softer.
SoundClip footstep() {
    const int n = int(0.30 * kRate);
    std::vector<double> out(n);
    LowPass heel(900.0), toe(1400.0);
    for (int i = 0; i < n; ++i) {
        const double t = double(i) / kRate;
        const double heelEnvelope = (1.0 - portableExp(-t / 0.002)) * portableExp(-t / 0.045);
        const double tt = t - 0.060;
        const double toeEnvelope = tt < 0.0 ? 0.0 : 0.45 * (1.0 - portableExp(-tt / 0.002)) * portableExp(-tt / 0.030);
        const double thump = 0.6 * portableSin(2.0 * kPi * 85.0 * t) * portableExp(-t / 0.050) * (1.0 - portableExp(-t / 0.003));
        out[i] = heel(noise(11, i)) * 3.0 * heelEnvelope + toe(noise(12, i)) * 3.0 * toeEnvelope + thump;
    }
    return toClip(out, 0.8, "footstep");
}

// A spark: a sine sweeping up from 2 kHz to 6 kHz in 0.12 s, fading with
// 60 ms, over 48 seeded clicks of high-passed noise (1 ms each), sparser and
// fainter as the burst dies out (150 ms).
SoundClip spark() {
    const int n = int(0.45 * kRate);
    std::vector<double> out(n, 0.0);
    double phase = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = double(i) / kRate;
        const double frequency = 2000.0 + 4000.0 * std::min(t / 0.12, 1.0);
        phase += 2.0 * kPi * frequency / kRate;
        if (phase > 2.0 * kPi) phase -= 2.0 * kPi;
        out[i] = 0.5 * portableSin(phase) * portableExp(-t / 0.060) * (1.0 - portableExp(-t / 0.001));
    }
    for (int click = 0; click < 48; ++click) {
        LowPass body(2500.0);   // noise minus its low-passed self: the bright part of the click
        // Start times bunch up early: the square of a uniform number.
        const double u = hash32(1000u + click) / 4294967296.0;
        const double start = 0.40 * u * u;
        const double amplitude = (0.4 + 0.6 * (hash32(2000u + click) / 4294967296.0)) * portableExp(-start / 0.150);
        const int first = int(start * kRate);
        for (int i = first; i < std::min(n, first + int(0.006 * kRate)); ++i) {
            const double t = double(i - first) / kRate;
            const double x = noise(3000u + click, i);
            out[i] += amplitude * (x - body(x)) * portableExp(-t / 0.001);
        }
    }
    return toClip(out, 0.8, "spark");
}

// Wind: white noise through a band-pass whose centre wanders between about
// 250 and 800 Hz, over a low rumble, with slow gusts. Every modulation is
// periodic in the clip's length, and the noise's last `fade` samples are
// cross-faded (equal power) into its first ones, so the loop has no seam:
// the sample after the last is, to the filter, the one that came next.
SoundClip ambientWind() {
    const double seconds = 4.0;
    const int n = int(seconds * kRate), fade = int(0.25 * kRate);
    const auto cycle = [&](int i, double cycles, double offset) {
        return portableSin(2.0 * kPi * (cycles * double(i % n) / n + offset));
    };
    std::vector<double> raw(n + fade);
    BandPass whistle;
    LowPass rumble(150.0);
    for (int i = 0; i < n + fade; ++i) {
        const double centre = 480.0 + 220.0 * cycle(i, 1.0, 0.0) + 90.0 * cycle(i, 3.0, 0.2);
        raw[i] = whistle(noise(21, i), centre, 2.0) + 2.5 * rumble(noise(22, i));
    }
    std::vector<double> out(n);
    for (int i = 0; i < n; ++i) {
        out[i] = raw[i];
        if (i < fade) {
            const double w = 0.5 * kPi * (i + 0.5) / fade;
            out[i] = raw[i] * portableSin(w) + raw[n + i] * portableCos(w);
        }
        const double gust = 0.65 + 0.22 * cycle(i, 2.0, 0.1) + 0.13 * cycle(i, 5.0, 0.7);
        out[i] *= gust;
    }
    return toClip(out, 0.6, "ambient_wind");
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream file(path, std::ios::binary);
    file.write(bytes.data(), std::streamsize(bytes.size()));
    if (!file) throw InputError(path.string(), 0, "cannot write the file");
}

} // namespace

const std::vector<std::string>& soundFileNames() {
    static const std::vector<std::string> names{"footstep.ogg", "spark.ogg", "ambient_wind.ogg"};
    return names;
}

SoundClip synthesizeSound(const std::string& name) {
    if (name == "footstep") return footstep();
    if (name == "spark") return spark();
    if (name == "ambient_wind") return ambientWind();
    throw std::invalid_argument("synthesizeSound(): no sound named '" + name + "' (footstep, spark, ambient_wind)");
}

// libvorbis's encoding loop (its documented use): three header packets, then
// blocks of analysed audio packed into Ogg pages.
void writeOggVorbis(const std::filesystem::path& path, const SoundClip& clip, float quality) {
    vorbis_info info;
    vorbis_info_init(&info);
    if (vorbis_encode_init_vbr(&info, clip.channels(), clip.sampleRate(), quality) != 0) {
        vorbis_info_clear(&info);
        throw InputError(path.string(), 0, "libvorbis refuses to encode " + std::to_string(clip.sampleRate()) +
                                               " Hz at quality " + std::to_string(quality));
    }
    vorbis_comment comment;
    vorbis_comment_init(&comment);
    vorbis_comment_add_tag(&comment, "TITLE", clip.name().c_str());
    vorbis_comment_add_tag(&comment, "COMMENT", "Generated by stoa-generate-assets (assets/generator); do not edit by hand.");
    vorbis_dsp_state dsp;
    vorbis_analysis_init(&dsp, &info);
    vorbis_block block;
    vorbis_block_init(&dsp, &block);
    ogg_stream_state stream;
    ogg_stream_init(&stream, 0x53746f61);   // "Stoa": a fixed serial number, so the bytes repeat

    std::string bytes;
    ogg_page page;
    const auto append = [&](const ogg_page& p) {
        bytes.append(reinterpret_cast<const char*>(p.header), std::size_t(p.header_len));
        bytes.append(reinterpret_cast<const char*>(p.body), std::size_t(p.body_len));
    };
    ogg_packet identification, comments, codebooks;
    vorbis_analysis_headerout(&dsp, &comment, &identification, &comments, &codebooks);
    ogg_stream_packetin(&stream, &identification);
    ogg_stream_packetin(&stream, &comments);
    ogg_stream_packetin(&stream, &codebooks);
    while (ogg_stream_flush(&stream, &page) != 0) append(page);   // the audio starts on a page of its own

    const std::vector<std::int16_t>& samples = clip.samples();
    const std::size_t frames = clip.frameCount();
    const int channels = clip.channels();
    const auto drain = [&] {
        ogg_packet packet;
        while (vorbis_analysis_blockout(&dsp, &block) == 1) {
            vorbis_analysis(&block, nullptr);
            vorbis_bitrate_addblock(&block);
            while (vorbis_bitrate_flushpacket(&dsp, &packet) != 0) {
                ogg_stream_packetin(&stream, &packet);
                while (ogg_stream_pageout(&stream, &page) != 0) append(page);
            }
        }
    };
    for (std::size_t at = 0; at < frames; at += 1024) {
        const int count = int(std::min<std::size_t>(1024, frames - at));
        float** buffer = vorbis_analysis_buffer(&dsp, count);
        for (int i = 0; i < count; ++i) {
            for (int c = 0; c < channels; ++c) buffer[c][i] = samples[(at + i) * channels + c] / 32768.0f;
        }
        vorbis_analysis_wrote(&dsp, count);
        drain();
    }
    vorbis_analysis_wrote(&dsp, 0);   // the end of the stream
    drain();
    while (ogg_stream_flush(&stream, &page) != 0) append(page);

    ogg_stream_clear(&stream);
    vorbis_block_clear(&block);
    vorbis_dsp_clear(&dsp);
    vorbis_comment_clear(&comment);
    vorbis_info_clear(&info);
    writeBytes(path, bytes);
}

void generateSounds(const std::filesystem::path& folder) {
    std::filesystem::create_directories(folder);
    for (const std::string& file : soundFileNames()) {
        const std::string name = std::filesystem::path(file).stem().string();
        // Quality 0 (about 64 kbit/s for 44.1 kHz stereo; less for mono): each file stays small.
        writeOggVorbis(folder / file, synthesizeSound(name), 0.0f);
    }
}

} // namespace stoa::assets
