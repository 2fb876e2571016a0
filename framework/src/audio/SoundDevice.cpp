#include <stoa/audio/SoundDevice.hpp>

#include <stoa/core/Assert.hpp>

#include <AL/al.h>
#include <AL/alc.h>

#include <glm/geometric.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>

namespace stoa {

namespace {

int g_openDevices = 0;   // OpenAL has one current context per process: one open SoundDevice at a time

/// Whether the machine may have a sound card. Linux lists them in
/// /proc/asound/cards; elsewhere there is no such list, and OpenAL is asked.
bool kernelListsSoundCard() {
#ifdef __linux__
    std::ifstream cards("/proc/asound/cards");
    if (!cards) return false;
    std::string line;
    while (std::getline(cards, line)) {
        if (line.find("no soundcards") != std::string::npos) return false;
        if (!line.empty()) return true;
    }
    return false;
#else
    return true;
#endif
}

bool fileSetsDrivers(const std::string& path) {
    std::ifstream file(path);
    static const std::regex drivers(R"(^\s*drivers\s*=)");
    std::string line;
    while (std::getline(file, line)) {
        if (std::regex_search(line, drivers)) return true;
    }
    return false;
}

/// Whether the user chose OpenAL Soft's backends: ALSOFT_DRIVERS, or a
/// "drivers =" line in a config file OpenAL Soft 1.19 reads.
bool userChoseDrivers() {
    if (std::getenv("ALSOFT_DRIVERS")) return true;
    std::vector<std::string> files = {"/etc/openal/alsoft.conf", "/etc/xdg/alsoft.conf"};
    if (const char* conf = std::getenv("ALSOFT_CONF")) files.push_back(conf);
    const char* home = std::getenv("HOME");
    if (home) files.push_back(std::string(home) + "/.alsoftrc");
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME")) files.push_back(std::string(xdg) + "/alsoft.conf");
    else if (home) files.push_back(std::string(home) + "/.config/alsoft.conf");
    for (const std::string& file : files) {
        if (fileSetsDrivers(file)) return true;
    }
    return false;
}

std::string deviceSpecifier(ALCdevice* device) {
    const ALCchar* name = alcGetString(device, ALC_DEVICE_SPECIFIER);
    return name ? name : "";
}

void printOff(const std::string& reason) { std::fprintf(stderr, "sound: off (%s)\n", reason.c_str()); }

// A handle packs a source slot (low 8 bits, slot + 1) and the slot's
// generation (the rest), so a handle to a sound that ended does not reach
// the next sound that reuses its source.
constexpr std::uint32_t kSlotBits = 8;
static_assert(SoundDevice::maxSources < (1 << kSlotBits), "a slot index must fit its bits");

} // namespace

struct SoundDevice::Impl {
    struct Slot {
        ALuint source = 0;
        std::uint32_t generation = 1;
        bool busy = false;
        bool oneShot = false;
    };

    ALCdevice* device = nullptr;
    ALCcontext* context = nullptr;
    std::vector<ALuint> buffers;   // per SoundBuffer id - 1; 0 where an upload failed
    std::vector<Slot> slots;

    ~Impl() {
        for (Slot& slot : slots) alSourceStop(slot.source);
        for (Slot& slot : slots) alDeleteSources(1, &slot.source);
        for (ALuint buffer : buffers) {
            if (buffer) alDeleteBuffers(1, &buffer);
        }
        alcMakeContextCurrent(nullptr);
        if (context) alcDestroyContext(context);
        // Closing stops the mixer; the wave backend writes its header's sizes now.
        if (device) alcCloseDevice(device);
        --g_openDevices;
    }

    Slot* find(SoundHandle sound) {
        const std::uint32_t index = (sound.id & ((1u << kSlotBits) - 1)) - 1;
        if (sound.id == 0 || index >= slots.size()) return nullptr;
        Slot& slot = slots[index];
        return slot.busy && slot.generation == (sound.id >> kSlotBits) ? &slot : nullptr;
    }

    void release(Slot& slot) {
        alSourceStop(slot.source);
        alSourcei(slot.source, AL_BUFFER, 0);
        slot.busy = false;
        slot.generation = (slot.generation + 1) & ((1u << (32 - kSlotBits)) - 1);
        if (slot.generation == 0) slot.generation = 1;
    }

    /// A free slot's handle (after freeing ended one-shots if none is free), or 0.
    SoundHandle start(ALuint buffer, bool oneShot) {
        for (int pass = 0; pass < 2; ++pass) {
            for (std::size_t i = 0; i < slots.size(); ++i) {
                Slot& slot = slots[i];
                if (slot.busy) continue;
                slot.busy = true;
                slot.oneShot = oneShot;
                alSourcei(slot.source, AL_BUFFER, ALint(buffer));
                return SoundHandle{slot.generation << kSlotBits | std::uint32_t(i + 1)};
            }
            reclaim();
        }
        return {};
    }

    void reclaim() {
        for (Slot& slot : slots) {
            if (!slot.busy || !slot.oneShot) continue;
            ALint state = AL_STOPPED;
            alGetSourcei(slot.source, AL_SOURCE_STATE, &state);
            if (state == AL_STOPPED) release(slot);
        }
    }
};

SoundDevice::SoundDevice(std::unique_ptr<Impl> impl, std::string offReason)
    : m_impl(std::move(impl)), m_offReason(std::move(offReason)) {}

SoundDevice SoundDevice::off(const std::string& reason) {
    printOff(reason);
    return SoundDevice(nullptr, reason);
}

SoundDevice::SoundDevice() {
    STOA_ASSERT(g_openDevices == 0, "SoundDevice: another SoundDevice is open. OpenAL has one current context per "
                                    "program: make one SoundDevice and pass it to what plays sounds.");
    // setenv(..., 0) keeps what the user set. Both matter only before the
    // process's first device opens: OpenAL Soft reads them once.
    setenv("ALSOFT_LOGLEVEL", "0", 0);
    const bool noCard = !kernelListsSoundCard();
    const bool quietDrivers = noCard && !userChoseDrivers();
    if (quietDrivers) setenv("ALSOFT_DRIVERS", "pulse,jack", 0);

    auto impl = std::make_unique<Impl>();
    ++g_openDevices;
    impl->device = alcOpenDevice(nullptr);
    if (!impl->device) {
        m_offReason = quietDrivers ? "no audio device: the system lists no sound card and no sound server answered"
                                   : "no audio device: OpenAL Soft could not open the default device; "
                                     "ALSOFT_LOGLEVEL=3 shows why";
        printOff(m_offReason);
        return;   // impl goes: it closes nothing and gives back the open count
    }
    impl->context = alcCreateContext(impl->device, nullptr);
    if (!impl->context || !alcMakeContextCurrent(impl->context)) {
        m_offReason = "no audio device: OpenAL Soft opened '" + deviceSpecifier(impl->device) +
                      "' but could not make a context on it";
        printOff(m_offReason);
        return;
    }
    alDistanceModel(AL_INVERSE_DISTANCE_CLAMPED);
    for (int i = 0; i < maxSources; ++i) {
        ALuint source = 0;
        alGetError();
        alGenSources(1, &source);
        if (alGetError() != AL_NO_ERROR) break;   // fewer sources than asked: play() runs out sooner
        alSourcef(source, AL_REFERENCE_DISTANCE, 1.0f);
        alSourcef(source, AL_ROLLOFF_FACTOR, 1.0f);
        impl->slots.push_back({source});
    }
    m_impl = std::move(impl);
}

SoundDevice::~SoundDevice() = default;
SoundDevice::SoundDevice(SoundDevice&&) noexcept = default;
SoundDevice& SoundDevice::operator=(SoundDevice&&) noexcept = default;

bool SoundDevice::enabled() const { return m_impl != nullptr; }
const std::string& SoundDevice::offReason() const { return m_offReason; }

std::string SoundDevice::deviceName() const {
    return m_impl ? deviceSpecifier(m_impl->device) : "";
}

SoundBuffer SoundDevice::upload(const SoundClip& clip) {
    STOA_ASSERT(!clip.empty(), "SoundDevice::upload(): the clip is empty. Load it with SoundClip::fromFile() first.");
    m_bufferChannels.push_back(clip.channels());
    if (m_impl) {
        ALuint buffer = 0;
        alGetError();
        alGenBuffers(1, &buffer);
        alBufferData(buffer, clip.channels() == 1 ? AL_FORMAT_MONO16 : AL_FORMAT_STEREO16, clip.samples().data(),
                     ALsizei(clip.samples().size() * sizeof(std::int16_t)), clip.sampleRate());
        if (alGetError() != AL_NO_ERROR) {
            std::fprintf(stderr, "sound: cannot upload '%s' (OpenAL is out of memory?); it will not play\n",
                         clip.name().c_str());
            alDeleteBuffers(1, &buffer);
            buffer = 0;
        }
        m_impl->buffers.push_back(buffer);
    }
    return SoundBuffer{std::uint32_t(m_bufferChannels.size())};
}

void SoundDevice::setListener(glm::vec3 positionWorld, glm::vec3 forwardWorld, glm::vec3 upWorld) {
    STOA_ASSERT(glm::length(glm::cross(forwardWorld, upWorld)) > 1e-6f,
                "SoundDevice::setListener(): forward and up are zero or parallel. Pass the camera's view "
                "direction and a world up such as (0, 1, 0).");
    if (!m_impl) return;
    alListener3f(AL_POSITION, positionWorld.x, positionWorld.y, positionWorld.z);
    const ALfloat orientation[6] = {forwardWorld.x, forwardWorld.y, forwardWorld.z, upWorld.x, upWorld.y, upWorld.z};
    alListenerfv(AL_ORIENTATION, orientation);
}

SoundHandle SoundDevice::play(SoundBuffer buffer, glm::vec3 positionWorld, float gain, bool loop) {
    STOA_ASSERT(buffer.id >= 1 && buffer.id <= m_bufferChannels.size(),
                "SoundDevice::play(): the buffer is 0 or comes from another device. Use what upload() returned.");
    STOA_ASSERT(m_bufferChannels[buffer.id - 1] == 1,
                "SoundDevice::play(): the buffer is stereo, and OpenAL places only mono sounds in the world. "
                "Upload clip.mono() for a placed sound, or use playAmbient() for one that is not placed.");
    if (!m_impl || !m_impl->buffers[buffer.id - 1]) return {};
    const SoundHandle sound = m_impl->start(m_impl->buffers[buffer.id - 1], !loop);
    Impl::Slot* slot = m_impl->find(sound);
    if (!slot) return {};
    alSourcei(slot->source, AL_SOURCE_RELATIVE, AL_FALSE);
    alSource3f(slot->source, AL_POSITION, positionWorld.x, positionWorld.y, positionWorld.z);
    alSourcef(slot->source, AL_GAIN, gain);
    alSourcei(slot->source, AL_LOOPING, loop ? AL_TRUE : AL_FALSE);
    alSourcePlay(slot->source);
    return sound;
}

SoundHandle SoundDevice::playAmbient(SoundBuffer buffer, float gain) {
    STOA_ASSERT(buffer.id >= 1 && buffer.id <= m_bufferChannels.size(),
                "SoundDevice::playAmbient(): the buffer is 0 or comes from another device. Use what upload() returned.");
    if (!m_impl || !m_impl->buffers[buffer.id - 1]) return {};
    const SoundHandle sound = m_impl->start(m_impl->buffers[buffer.id - 1], false);
    Impl::Slot* slot = m_impl->find(sound);
    if (!slot) return {};
    // Relative to the listener, at its centre: heard the same wherever the camera goes.
    alSourcei(slot->source, AL_SOURCE_RELATIVE, AL_TRUE);
    alSource3f(slot->source, AL_POSITION, 0.0f, 0.0f, 0.0f);
    alSourcef(slot->source, AL_GAIN, gain);
    alSourcei(slot->source, AL_LOOPING, AL_TRUE);
    alSourcePlay(slot->source);
    return sound;
}

void SoundDevice::setPosition(SoundHandle sound, glm::vec3 positionWorld) {
    if (Impl::Slot* slot = m_impl ? m_impl->find(sound) : nullptr) {
        alSource3f(slot->source, AL_POSITION, positionWorld.x, positionWorld.y, positionWorld.z);
    }
}

void SoundDevice::setGain(SoundHandle sound, float gain) {
    if (Impl::Slot* slot = m_impl ? m_impl->find(sound) : nullptr) alSourcef(slot->source, AL_GAIN, gain);
}

void SoundDevice::stop(SoundHandle sound) {
    if (Impl::Slot* slot = m_impl ? m_impl->find(sound) : nullptr) m_impl->release(*slot);
}

bool SoundDevice::playing(SoundHandle sound) const {
    Impl::Slot* slot = m_impl ? m_impl->find(sound) : nullptr;
    if (!slot) return false;
    ALint state = AL_STOPPED;
    alGetSourcei(slot->source, AL_SOURCE_STATE, &state);
    return state == AL_PLAYING;
}

int SoundDevice::sourcesInUse() const {
    if (!m_impl) return 0;
    int busy = 0;
    for (const Impl::Slot& slot : m_impl->slots) busy += slot.busy ? 1 : 0;
    return busy;
}

void SoundDevice::setMuted(bool muted) {
    m_muted = muted;
    if (m_impl) alListenerf(AL_GAIN, muted ? 0.0f : 1.0f);
}

void SoundDevice::update() {
    if (m_impl) m_impl->reclaim();
}

} // namespace stoa
