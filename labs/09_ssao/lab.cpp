// Lab 09 app: the Acropolis by day, its ambient light darkened in corners and
// creases by screen-space ambient occlusion. Lab 08's G-buffer (your
// g_buffer.glsl) is drawn first; the occlusion pass (shaders/ssao/ssao.frag,
// your ssao.glsl) estimates, per pixel, how much of the hemisphere above the
// surface the scene hides, with your kernel and noise (kernel.cpp); the blur
// pass smooths it; stoa::DeferredRenderer's ambient pass multiplies the
// ambient light by it.
//
// Case keys besides the camera's (CameraRig.hpp):
//   view = final | ambient | raw | blurred | without
//            final: the lit picture; ambient: only a white ambient light (times
//            the occlusion); raw / blurred: the occlusion itself, before and after
//            the blur; without: the lit picture with no occlusion (default final)
//   kernel = n          samples, 1..64 (default 32)
//   radius = metres     the hemisphere's radius in view space, (0, 5] (default 1)
//   bias = metres       depth bias of the comparison, [0, 0.5] (default 0.025)
//   kernel_seed = n     (default 1)       noise_seed = n   (default 2)
//   lights = n          wandering lights of lab 08, 0..1024 (default 0)
// In the window: v switches the view, o the occlusion on and off, k the kernel size.

#include "checks.hpp"
#include "lab09.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/AmbientOcclusion.hpp>
#include <stoa/render/AmbientOcclusionPass.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/render/TextureOverlay.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/PieceDrawList.hpp>
#include <stoa/scene/WanderingLights.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace {

const std::vector<std::string> kViews{"final", "ambient", "raw", "blurred", "without"};
enum class View { Final, Ambient, Raw, Blurred, Without };

constexpr int kViewUnit = 11;   // the occlusion views' texture

class AmbientOcclusionLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        m_resources = &resources;
        const auto load = [&](const std::string& vertex, const std::string& fragment) -> const stoa::Program& {
            return resources.loadProgram(vertex, fragment);
        };
        const stoa::DeferredPrograms programs = stoa::DeferredPrograms::load(load);
        m_occlusion = std::make_unique<stoa::AmbientOcclusionPass>(load("basic/image.vert", "ssao/ssao.frag"),
                                                                    load("basic/image.vert", "ssao/blur.frag"));
        m_viewProgram = &resources.loadProgram("basic/image.vert", "ssao/ao_view.frag");
        m_renderer = std::make_unique<stoa::DeferredRenderer>(programs);
        m_overlay = std::make_unique<stoa::TextureOverlay>();
        m_scene = std::make_unique<stoa::PieceDrawList>(stoa::acropolisPieces());
        m_lighting.ambient = glm::vec3(0.62f, 0.64f, 0.68f);
        m_lighting.moon = stoa::acropolisSun();
        m_lighting.moon.color *= 0.45f;
        m_lighting.sky = glm::vec3(0.55f, 0.68f, 0.85f);
    }

    void loadCase(const stoa::CaseSpec& spec) override {
        m_cameras.loadCase(spec);
        const std::string view = spec.getChoice("view", kViews, std::string("final"));
        for (std::size_t i = 0; i < kViews.size(); ++i)
            if (view == kViews[i]) m_view = static_cast<View>(i);
        m_kernelSize = spec.getIntInRange("kernel", 1, stoa::kMaxKernelSize, 32);
        m_radius = static_cast<float>(spec.getNumber("radius", 1.0));
        if (!(m_radius > 0.0f && m_radius <= 5.0f)) spec.reject("radius", "radius must be in (0, 5] metres");
        m_bias = static_cast<float>(spec.getNumber("bias", 0.025));
        if (!(m_bias >= 0.0f && m_bias <= 0.5f)) spec.reject("bias", "bias must be in [0, 0.5] metres");
        m_kernelSeed = static_cast<std::uint32_t>(spec.getIntInRange("kernel_seed", 0, 1000000, 1));
        m_noiseSeed = static_cast<std::uint32_t>(spec.getIntInRange("noise_seed", 0, 1000000, 2));
        m_lightOptions.count = spec.getIntInRange("lights", 0, 1024, 0);
        m_kernelChanged = true;
    }

    void render(glm::ivec2 size) override {
        const GLuint output = stoa::StateCache::current().drawFramebuffer();
        const stoa::Camera& camera = m_cameras.active();
        m_renderer->renderGeometry(m_scene->items(), camera, size);   // lab 01's camera and lab 08's G-buffer first
        if (m_kernelChanged) {
            // The student's kernel and noise, once per case.
            const std::vector<glm::vec3> kernel = stoa::ssaoKernel(m_kernelSize, m_kernelSeed);
            m_occlusion->setKernel(kernel, stoa::ssaoNoise(m_noiseSeed));
            m_kernelChanged = false;
        }
        const bool occlusion = m_view != View::Without;
        if (occlusion) m_occlusion->render(*m_renderer, size, {m_radius, m_bias});
        stoa::StateCache::current().bindFramebuffer(output);
        if (m_view == View::Raw || m_view == View::Blurred) {
            (m_view == View::Raw ? m_occlusion->raw() : m_occlusion->blurred()).bind(kViewUnit);
            m_viewProgram->use();
            m_viewProgram->set("uImage", kViewUnit);
            m_overlay->draw(*m_viewProgram, {0, 0, size.x, size.y});
            return;
        }
        stoa::SceneLighting lighting = m_lighting;
        std::vector<stoa::PointLight> lights = stoa::wanderingLights(m_lightOptions, 0.0f);
        if (m_view == View::Ambient) {   // albedo times the occlusion: white ambient light, nothing else
            lighting.ambient = glm::vec3(1.0f);
            lighting.moon.color = glm::vec3(0.0f);
            lights.clear();
        }
        stoa::DeferredSettings settings;
        settings.reuseGBuffer = true;
        settings.ambientOcclusion = occlusion ? &m_occlusion->blurred() : nullptr;
        m_renderer->render(m_scene->items(), lights, lighting, camera, size, settings);
    }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    stoa::CheckResult runCheck(const stoa::CaseSpec& spec) override {
        if (spec.check == "kernel_in_order") return lab09::checkKernelInOrder();
        if (spec.check == "range_check_from_the_point") {
            throwIfShaderStubs();   // it draws through the G-buffer and occlusion programs
            m_kernelChanged = true;   // the check sets a kernel of its own
            return lab09::checkRangeCheckFromThePoint(*m_renderer, *m_occlusion);
        }
        if (spec.check == "blur_footprint") {
            throwIfShaderStubs();   // it draws through the occlusion and blur programs
            m_kernelChanged = true;   // the check sets a kernel of its own
            return lab09::checkBlurFootprint(*m_renderer, *m_occlusion);
        }
        return Lab::runCheck(spec);
    }

    bool keyPressed(unsigned char key) override {
        if (key == 'v') {
            m_view = static_cast<View>((static_cast<int>(m_view) + 1) % static_cast<int>(kViews.size()));
            std::printf("view: %s\n", kViews[static_cast<std::size_t>(m_view)].c_str());
            return true;
        }
        if (key == 'o') {
            m_view = m_view == View::Without ? View::Final : View::Without;
            std::printf("ambient occlusion %s\n", m_view == View::Without ? "off" : "on");
            return true;
        }
        if (key == 'k') {
            m_kernelSize = m_kernelSize >= stoa::kMaxKernelSize ? 8 : std::min(m_kernelSize * 2, stoa::kMaxKernelSize);
            m_kernelChanged = true;
            std::printf("kernel: %d samples\n", m_kernelSize);
            return true;
        }
        return false;
    }

    std::vector<std::string> keyHelp() const override {
        return {"v            switch view: final / ambient only / raw occlusion / blurred occlusion / without occlusion",
                "o            occlusion on and off",
                "k            kernel size: 8, 16, 32, 64 samples"};
    }

private:
    // A check that draws is not attempted while a GLSL stub is in its programs,
    // as a picture case is not (the framework runs checks as C++ only).
    void throwIfShaderStubs() const {
        for (const auto& program : m_resources->programs()) {
            if (program->stubs().empty()) continue;
            const stoa::ShaderStub& stub = program->stubs().front();
            const std::filesystem::path file(stub.file);
            throw stoa::NotImplemented(stub.function + "() (" + file.filename().string() + ":" + std::to_string(stub.line) + ")",
                                       file.parent_path().parent_path().filename().string());
        }
    }

    stoa::LabResources* m_resources = nullptr;
    stoa::CameraRig m_cameras;
    std::unique_ptr<stoa::DeferredRenderer> m_renderer;
    std::unique_ptr<stoa::PieceDrawList> m_scene;
    std::unique_ptr<stoa::AmbientOcclusionPass> m_occlusion;
    const stoa::Program* m_viewProgram = nullptr;
    std::unique_ptr<stoa::TextureOverlay> m_overlay;   // made once the context exists
    stoa::SceneLighting m_lighting;
    stoa::WanderingLightsOptions m_lightOptions;
    bool m_kernelChanged = true;   // a new case or kernel size: setKernel() before the next frame
    View m_view = View::Final;
    int m_kernelSize = 32;
    float m_radius = 1.0f;
    float m_bias = 0.025f;
    std::uint32_t m_kernelSeed = 1;
    std::uint32_t m_noiseSeed = 2;
};

} // namespace

int main(int argc, char** argv) {
    AmbientOcclusionLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
