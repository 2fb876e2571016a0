#pragma once
// Positional sound through OpenAL Soft: one listener (it follows the camera),
// clips uploaded once as buffers, and sounds played from them at points of
// the world or as a looping ambient bed.
//
//   SoundDevice sound;                                   // the default output device, or sound off
//   SoundBuffer step = sound.upload(SoundClip::fromFile(paths::assetsDir() / "sounds/footstep.ogg"));
//   SoundBuffer wind = sound.upload(SoundClip::fromFile(paths::assetsDir() / "sounds/ambient_wind.ogg"));
//   sound.playAmbient(wind, 0.4f);
//   // every frame:
//   sound.setListener(camera.position(), camera.forward(), glm::vec3(0, 1, 0));
//   if (stepped) sound.play(step, feetWorld);
//   sound.update();                                      // frees the sources of finished sounds
//
// Only MONO sounds are placed in the world: OpenAL plays a stereo buffer as it
// is, the same wherever its source stands, so play() refuses a stereo buffer
// (upload clip.mono() instead); playAmbient() takes either.
//
// With no sound card, no sound server or no usable configuration, the device
// is "off": it prints one line, "sound: off (no audio device: ...)", to
// stderr, and every call still works and does nothing; no call throws for
// lack of sound. Attenuation is OpenAL's inverse distance, clamped: a sound
// of gain g at d >= 1 metres from the listener is heard at g / d.
//
// OpenAL Soft reads its configuration once per process, when the first
// device opens: ALSOFT_CONF names an extra config file, ALSOFT_DRIVERS the
// backends, ALSOFT_LOGLEVEL (Stoa makes it 0 when unset; 3 shows everything)
// how much it prints. docs/framework.md#sound shows how a test records the
// output to a WAV file with the "wave" backend.

#include <stoa/audio/SoundClip.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace stoa {

/// A clip uploaded to a SoundDevice. 0: none.
struct SoundBuffer {
    std::uint32_t id = 0;
};

/// One playing sound. 0: none (sound off, or every source busy). Every call
/// takes a handle whose sound has ended, or 0, and does nothing with it.
struct SoundHandle {
    std::uint32_t id = 0;
    explicit operator bool() const { return id != 0; }
};

class SoundDevice {
public:
    /// Sounds that can play at once; play() gives 0 while all are busy.
    static constexpr int maxSources = 32;

    /// Opens the default output device, or turns sound off with one line on
    /// stderr saying why. Before the first device of the process opens, and
    /// only where the user set nothing: ALSOFT_LOGLEVEL becomes 0 (OpenAL
    /// Soft's own errors would repeat ours), and on a machine whose kernel
    /// lists no sound card ALSOFT_DRIVERS becomes "pulse,jack" (the sound
    /// servers), so ALSA does not print a page of "cannot find card '0'".
    /// Only one SoundDevice may be open at a time.
    SoundDevice();
    /// A device with sound off from the start (a --no-sound flag); prints the line with `reason`.
    static SoundDevice off(const std::string& reason);
    /// Stops every sound and closes the device (which, for the "wave"
    /// backend, finishes the WAV file's header).
    ~SoundDevice();

    SoundDevice(SoundDevice&&) noexcept;
    SoundDevice& operator=(SoundDevice&&) noexcept;
    SoundDevice(const SoundDevice&) = delete;
    SoundDevice& operator=(const SoundDevice&) = delete;

    /// Whether sound is on (a device is open).
    bool enabled() const;
    /// Why sound is off ("" when it is on).
    const std::string& offReason() const;
    /// The device OpenAL opened ("" when off).
    std::string deviceName() const;

    /// Uploads a clip (mono or stereo). The buffer lives as long as the device.
    SoundBuffer upload(const SoundClip& clip);

    /// The listener: where the camera is and where it looks, in world space
    /// (metres). `forward` and `up` need not be unit length, only not parallel.
    void setListener(glm::vec3 positionWorld, glm::vec3 forwardWorld, glm::vec3 upWorld);

    /// Plays a mono buffer from `positionWorld` with `gain` (1: as recorded).
    /// A one-shot sound (loop false) frees its source when it ends; a looping
    /// one plays until stop(). Asserts on a stereo buffer.
    SoundHandle play(SoundBuffer buffer, glm::vec3 positionWorld, float gain = 1.0f, bool loop = false);
    /// Loops a buffer (mono or stereo) at the listener, not placed in the
    /// world: wind, a crowd's murmur. Plays until stop().
    SoundHandle playAmbient(SoundBuffer buffer, float gain = 1.0f);
    /// Moves a playing sound (a looping one follows its object).
    void setPosition(SoundHandle sound, glm::vec3 positionWorld);
    void setGain(SoundHandle sound, float gain);
    void stop(SoundHandle sound);
    /// Whether the sound still plays (false for 0, a stopped or an ended one).
    bool playing(SoundHandle sound) const;
    /// Sounds holding a source now (finished one-shots count until update()).
    int sourcesInUse() const;

    /// Mute: the listener's gain goes to 0; sounds go on playing unheard.
    void setMuted(bool muted);
    bool muted() const { return m_muted; }

    /// Once a frame: frees the sources of one-shot sounds that have ended.
    void update();

private:
    struct Impl;
    explicit SoundDevice(std::unique_ptr<Impl> impl, std::string offReason);

    std::unique_ptr<Impl> m_impl;   // null when sound is off
    std::string m_offReason;
    std::vector<int> m_bufferChannels;   // per SoundBuffer id - 1, kept when off so misuse asserts everywhere
    bool m_muted = false;
};

} // namespace stoa
