// Lab 11's app: saved files and the clock for hot reload, the panel's
// texture, sound and the log.

#include "editor_app.hpp"

#include <stoa/core/InputFile.hpp>

#include <algorithm>

namespace stoa {

void EditorLabApp::saveFile(const std::string& name, double seconds) {
    ++m_fileVersions[name];
    m_changes.push_back({panelFile(name), seconds});
}

void EditorLabApp::tick(double now) {
    const std::vector<AssetFiles> assets = {{"panel", {panelFile("diffuse"), panelFile("stripes")}, m_panelLoadedAt}};
    for (const std::string& name : assetsToReload(m_changes, assets, now, m_debounce)) {
        if (name != "panel") continue;
        m_panelFiles = {m_fileVersions["diffuse"], m_fileVersions["stripes"]};
        m_panelLoadedAt = now;
        m_panelTexture.reset();
        char line[96];
        std::snprintf(line, sizeof line, "reloaded panel at %.2f s (diffuse v%d, stripes v%d)", now, m_panelFiles[0], m_panelFiles[1]);
        log(line);
    }
}

const Texture2D& EditorLabApp::panelTexture() {
    if (!m_panelTexture) {
        static const glm::vec3 colours[] = {{0.9f, 0.85f, 0.7f}, {0.3f, 0.55f, 0.9f}, {0.9f, 0.3f, 0.35f}, {0.35f, 0.8f, 0.4f}};
        const glm::vec3 paper = colours[m_panelFiles[0] % 4];
        const int stripes = 2 + 2 * (m_panelFiles[1] % 4);
        m_panelTexture = std::make_unique<Texture2D>(pictureTexture({64, 64}, [&](int x, int) {
            const bool ink = ((x * stripes) / 64) % 2 == 1;
            return ink ? paper * 0.35f : paper;
        }));
    }
    return *m_panelTexture;
}

void EditorLabApp::reloadChangedAssets() {
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_started).count();
    m_assets->update(now);
    for (const std::string& line : m_assets->takeLog()) log(line);
}

void EditorLabApp::updateSound(const Camera& camera) {
    if (!m_sound) {
        m_sound = std::make_unique<SoundDevice>();   // sound off, with one line, where there is no device
        if (!m_sound->enabled()) return;
        try {
            const auto clip = [](const char* name) { return SoundClip::fromFile(paths::assetsDir() / "sounds" / name).mono(); };
            m_sparkSound = m_sound->upload(clip("spark.ogg"));
            m_footstepSound = m_sound->upload(clip("footstep.ogg"));
            m_sound->playAmbient(m_sound->upload(clip("ambient_wind.ogg")), 0.25f);
        } catch (const std::exception& error) {
            log(std::string("sound: ") + error.what());
        }
    }
    m_sound->setListener(camera.eyePosition(), camera.lookTarget() - camera.eyePosition(), camera.upVector());
    if (m_pipeline) {
        // The crowd's footsteps (deferred pipeline): the nearest few of each frame, so that twenty
        // walkers do not take every source.
        std::vector<glm::vec3> steps = m_pipeline->takeFootsteps();
        const glm::vec3 ear = camera.eyePosition();
        std::sort(steps.begin(), steps.end(), [&](const glm::vec3& a, const glm::vec3& b) {
            return glm::length(a - ear) < glm::length(b - ear);
        });
        for (std::size_t i = 0; i < steps.size() && i < 3; ++i)
            if (glm::length(steps[i] - ear) < 40.0f && m_footstepSound.id != 0) m_sound->play(m_footstepSound, steps[i], 0.5f);
    }
    m_sound->update();
}

void EditorLabApp::playSound(SoundBuffer buffer, const glm::vec3& where) {
    if (m_sound && m_sound->enabled() && buffer.id != 0) m_sound->play(buffer, where, 0.8f);
}

void EditorLabApp::throwMissingAsset(const EditorAssets::Failure& failure) const {
    // The line of the scene file that names the asset (the first that does), or 0.
    int line = 0;
    try {
        const std::string text = readInputFile(m_sceneFile, EditorSceneFileLimits::maxFileBytes, "a scene file");
        const std::size_t at = text.find("\"" + failure.name + "\"");
        if (at != std::string::npos) line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    } catch (const InputError&) {   // the scene file went away: name it without a line
    }
    throw InputError(m_sceneFile.string(), line, failure.message);
}

void EditorLabApp::log(const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
    m_log.push_back(line);
    if (m_log.size() > 200) m_log.erase(m_log.begin());
}

} // namespace stoa
