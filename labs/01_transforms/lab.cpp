// Lab 01 app: the shapes scene through the student's matrices and cameras,
// shaded by a light at the eye (shaders/basic/headlight.*), so that what is
// graded is where things are, not how they are lit.

#include "checks.hpp"

#include <stoa/gl/Program.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/scene/ShapesScene.hpp>

namespace {

class TransformsLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        m_program = &resources.loadProgram("basic/headlight.vert", "basic/headlight.frag");
        stoa::buildShapesScene(m_scene);
    }

    void loadCase(const stoa::CaseSpec& spec) override { m_cameras.loadCase(spec); }

    void render(glm::ivec2 size) override { m_renderer.render(m_scene, m_cameras.active(), *m_program, size); }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    stoa::CheckResult runCheck(const stoa::CaseSpec& spec) override {
        if (spec.check == "camera_limits") return lab01::checkCameraLimits();
        if (spec.check == "matrices_map_the_frustum") return lab01::checkMatricesMapTheFrustum();
        return Lab::runCheck(spec);
    }

private:
    stoa::Scene m_scene;
    stoa::CameraRig m_cameras;
    stoa::ForwardRenderer m_renderer;
    stoa::Program* m_program = nullptr;
};

} // namespace

int main(int argc, char** argv) {
    TransformsLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
