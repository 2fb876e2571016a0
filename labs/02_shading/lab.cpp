// Lab 02 app: the shapes scene lit with the student's Blinn-Phong shaders
// (shaders/forward/blinn_phong.* include labs/02_shading/student/*.glsl), through the
// student's lab-01 matrices and cameras.
//
// Case keys besides the camera's (CameraRig.hpp):
//   ambient = r g b                      scene ambient light
//   sun = dx dy dz  r g b                a directional light (omit for none)
//   point_lights = N                     0..3 of the coloured point lights below
//   attenuation = kc kl kq               for the point lights
//   shininess_scale = s                  multiplies every material's exponent

#include <stoa/gl/Program.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/ShapesScene.hpp>

#include <vector>

namespace {

const stoa::PointLight kPointLights[] = {
    {{-2.5f, 2.0f, 2.0f}, {1.0f, 0.55f, 0.3f}, {1.0f, 0.09f, 0.032f}},
    {{2.5f, 1.5f, 1.5f}, {0.3f, 0.6f, 1.0f}, {1.0f, 0.09f, 0.032f}},
    {{0.0f, 2.5f, -2.5f}, {0.5f, 1.0f, 0.45f}, {1.0f, 0.09f, 0.032f}},
};

class ShadingLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        m_program = &resources.loadProgram("forward/blinn_phong.vert", "forward/blinn_phong.frag");
    }

    void loadCase(const stoa::CaseSpec& spec) override {
        stoa::buildShapesScene(m_scene);
        m_cameras.loadCase(spec);
        m_scene.ambient = spec.getVec3("ambient", glm::vec3(0.08f));
        if (spec.has("sun")) {
            const std::vector<float> sun = spec.getNumbers("sun", 6, "direction x y z, colour r g b");
            m_scene.directionalLights.push_back({{sun[0], sun[1], sun[2]}, {sun[3], sun[4], sun[5]}});
        }
        const int pointCount = spec.getIntInRange("point_lights", 0, 3, 0);
        const glm::vec3 attenuation = spec.getVec3("attenuation", glm::vec3(1.0f, 0.09f, 0.032f));
        for (int i = 0; i < pointCount; ++i) {
            stoa::PointLight light = kPointLights[i];
            light.attenuation = attenuation;
            m_scene.pointLights.push_back(light);
        }
        const float shininessScale = static_cast<float>(spec.getNumber("shininess_scale", 1.0));
        for (const auto& object : m_scene.objects())
            if (auto* meshObject = dynamic_cast<stoa::MeshObject*>(object.get()))
                meshObject->material.shininess *= shininessScale;
    }

    void render(glm::ivec2 size) override { m_renderer.render(m_scene, m_cameras.active(), *m_program, size); }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

private:
    stoa::Scene m_scene;
    stoa::CameraRig m_cameras;
    stoa::ForwardRenderer m_renderer;
    stoa::Program* m_program = nullptr;
};

} // namespace

int main(int argc, char** argv) {
    ShadingLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
