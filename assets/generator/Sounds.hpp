#pragma once
// The generated sounds (assets/sounds/): synthesised from seeded noise and
// sine waves, then written as Ogg Vorbis with libvorbis's encoder.
//
//   footstep      0.3 s mono: a heel and a toe, two low-passed noise bursts with a low thump
//   spark         0.45 s mono: a rising bright chirp with a crackle of short clicks
//   ambient_wind  4 s mono: band-passed noise with slow gusts; the loop has no seam
//
// The samples are the same bits on every machine (seeded hash noise, the
// generator's own sin and exp); the Ogg bytes are those of the libvorbis
// that encodes them, so the tests compare decoded sound, not bytes.

#include <stoa/audio/SoundClip.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::assets {

/// footstep.ogg, spark.ogg, ambient_wind.ogg.
const std::vector<std::string>& soundFileNames();
/// The samples of "footstep", "spark" or "ambient_wind" (44100 Hz, mono), before encoding.
SoundClip synthesizeSound(const std::string& name);
/// Encodes `clip` as Ogg Vorbis at `quality` (-0.1 = smallest .. 1 = best;
/// libvorbis's VBR scale) with a fixed stream serial number. Throws
/// InputError naming `path` when the encoder refuses or the file cannot be written.
void writeOggVorbis(const std::filesystem::path& path, const SoundClip& clip, float quality);
/// Writes the three sounds into `folder`.
void generateSounds(const std::filesystem::path& folder);

} // namespace stoa::assets
