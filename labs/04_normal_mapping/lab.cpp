// Lab 04 app: a stretch of the Acropolis wall (assets/acropolis/wall.obj),
// bump mapped with the normal map the student builds from its height map,
// lit in tangent space (shaders/normal_mapping/normal_mapped.* include
// labs/04_normal_mapping/student/tangent_space.glsl and lab 02's lighting.glsl).
// Beside the wall: a second piece of it with its u mirrored (where the
// tangent's handedness matters) and a bumped boulder (curved tangent frames).
//
// Case keys besides the camera's (CameraRig.hpp):
//   ambient = r g b                      scene ambient light
//   sun = dx dy dz  r g b                a directional light (omit for none)
//   point_light = x y z  r g b           a point light (omit for none)
//   attenuation = kc kl kq               for the point light
//   bump_strength = s                    normalMapFromHeight()'s strength (default 6)
//   view = shaded | normals              normals: the bumped world normal as a colour
//   normal_mapping = on | off            off: light with the mesh's own normals

#include "checks.hpp"
#include "lab04.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/Mesh.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/image/HeightMap.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/Scene.hpp>

#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace {

enum class View { Shaded = 0, Normals = 1 };  // the values of the shader's uDisplay

/// A MeshObject that also binds a normal map (uNormalMap, uHasNormalMap) on
/// the first texture unit MeshObject leaves free.
class BumpedObject : public stoa::MeshObject {
public:
    using MeshObject::MeshObject;

    std::shared_ptr<const stoa::Texture2D> normalMap;  // none: lit with the mesh's normals

    void setDrawUniforms(const stoa::Program& program) const override {
        // The sampler keeps its own unit even without a map (as MeshObject's do).
        program.set("uNormalMap", kFirstFreeTextureUnit);
        program.set("uHasNormalMap", normalMap != nullptr);
        if (normalMap) normalMap->bind(kFirstFreeTextureUnit);
    }
};

class NormalMappingLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        m_program = &resources.loadProgram("normal_mapping/normal_mapped.vert", "normal_mapping/normal_mapped.frag");
        const stoa::Model wall = stoa::loadObj(stoa::paths::assetsDir() / "acropolis" / "wall.obj");
        m_wall = wall.parts.front();
        const std::string heightPath = m_wall.material.heightMap.empty()
                                           ? (stoa::paths::assetsDir() / "acropolis" / "wall_height.pgm").string()
                                           : m_wall.material.heightMap;
        m_height = stoa::loadHeightMap(heightPath);
    }

    void loadCase(const stoa::CaseSpec& spec) override {
        m_cameras.loadCase(spec);
        m_scene.clear();
        m_scene.ambient = spec.getVec3("ambient", glm::vec3(0.06f));
        m_scene.directionalLights.clear();
        m_scene.pointLights.clear();
        if (spec.has("sun")) {
            const std::vector<float> sun = spec.getNumbers("sun", 6, "direction x y z, colour r g b");
            m_scene.directionalLights.push_back({{sun[0], sun[1], sun[2]}, {sun[3], sun[4], sun[5]}});
        }
        const glm::vec3 attenuation = spec.getVec3("attenuation", glm::vec3(1.0f, 0.09f, 0.032f));
        if (spec.has("point_light")) {
            const std::vector<float> light = spec.getNumbers("point_light", 6, "position x y z, colour r g b");
            m_scene.pointLights.push_back({{light[0], light[1], light[2]}, {light[3], light[4], light[5]}, attenuation});
        }
        const float strength = static_cast<float>(spec.getNumber("bump_strength", 6.0));
        if (!(strength > 0.0f)) spec.reject("bump_strength", "bump_strength must be greater than 0");
        m_view = spec.getChoice("view", {"shaded", "normals"}, std::string("shaded")) == "normals" ? View::Normals
                                                                                                  : View::Shaded;
        m_normalMapping = spec.getSwitch("normal_mapping", true);

        // Student code from here on: until it runs, render() reports the stub.
        m_missing = "computeTangents()";
        buildMeshes();
        m_missing = "normalMapFromHeight()";
        const std::shared_ptr<const stoa::Texture2D> normalMap = normalMapFor(strength);
        m_missing.reset();
        buildScene(normalMap);
    }

    void render(glm::ivec2 size) override {
        if (m_missing) throw stoa::NotImplemented(*m_missing);
        m_program->use();
        m_program->set("uNormalMapping", m_normalMapping);
        m_program->set("uDisplay", static_cast<int>(m_view));
        m_renderer.render(m_scene, m_cameras.active(), *m_program, size);
    }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    bool keyPressed(unsigned char key) override {
        if (key == 'n') {
            m_normalMapping = !m_normalMapping;
            std::printf("normal mapping %s\n", m_normalMapping ? "on" : "off");
            return true;
        }
        if (key == 'v') {
            m_view = m_view == View::Shaded ? View::Normals : View::Shaded;
            std::printf("view: %s\n", m_view == View::Shaded ? "shaded" : "normals as colour");
            return true;
        }
        return false;
    }

    stoa::CheckResult runCheck(const stoa::CaseSpec& spec) override {
        if (spec.check == "normal_map_wraps") return lab04::checkNormalMapWraps();
        if (spec.check == "normal_map_encoding") return lab04::checkNormalMapEncoding();
        if (spec.check == "tangents_without_nans") return lab04::checkTangentsWithoutNans();
        if (spec.check == "tangents_follow_the_uvs") return lab04::checkTangentsFollowTheUvs();
        return Lab::runCheck(spec);
    }

    std::vector<std::string> keyHelp() const override {
        return {"n            toggle normal mapping (off: the mesh's own normals)",
                "v            switch view: shaded / world normals as colour (n * 0.5 + 0.5)"};
    }

private:
    // The meshes need the student's tangents; they are built once, at the first case.
    void buildMeshes() {
        if (m_wallMesh) return;
        stoa::Mesh wall = m_wall.mesh;
        stoa::computeTangents(wall);
        // The same wall with u running the other way: a mirrored texture, as
        // modellers make to save texture space. Its bitangent is cross(N, T)
        // with the opposite sign: the handedness, w = -1.
        stoa::Mesh mirrored = m_wall.mesh;
        for (stoa::Vertex& vertex : mirrored.vertices) vertex.uv.x = -vertex.uv.x;
        stoa::computeTangents(mirrored);
        stoa::Mesh boulder = stoa::shapes::sphere(0.5f, 64, 32);
        for (stoa::Vertex& vertex : boulder.vertices) vertex.uv *= glm::vec2(3.0f, 1.5f);  // smaller stones
        stoa::computeTangents(boulder);
        stoa::Mesh floor = stoa::shapes::plane(1.0f, 1);
        stoa::computeTangents(floor);

        m_wallMesh = std::make_shared<const stoa::GpuMesh>(wall);
        m_mirroredMesh = std::make_shared<const stoa::GpuMesh>(mirrored);
        m_boulderMesh = std::make_shared<const stoa::GpuMesh>(boulder);
        m_floorMesh = std::make_shared<const stoa::GpuMesh>(floor);
    }

    // One normal map per strength a case asks for.
    std::shared_ptr<const stoa::Texture2D> normalMapFor(float strength) {
        auto found = m_normalMaps.find(strength);
        if (found != m_normalMaps.end()) return found->second;
        const stoa::Image normals = stoa::normalMapFromHeight(m_height, strength);
        auto texture = std::make_shared<const stoa::Texture2D>(stoa::Texture2D::fromImage(normals));
        m_normalMaps.emplace(strength, texture);
        return texture;
    }

    void buildScene(const std::shared_ptr<const stoa::Texture2D>& normalMap) {
        stoa::Material stone;
        stone.name = "boulder";
        stone.ambient = stone.diffuse = glm::vec3(0.78f, 0.74f, 0.66f);
        stone.specular = glm::vec3(0.25f);
        stone.shininess = 24.0f;
        stoa::Material ground;
        ground.name = "ground";
        ground.ambient = ground.diffuse = glm::vec3(0.45f, 0.43f, 0.40f);
        ground.specular = glm::vec3(0.05f);
        ground.shininess = 8.0f;

        auto add = [&](const std::shared_ptr<const stoa::GpuMesh>& mesh, const stoa::Material& material,
                       const char* name, glm::vec3 position, float yawDegrees, glm::vec3 scale,
                       std::shared_ptr<const stoa::Texture2D> map) {
            BumpedObject& object = m_scene.add(std::make_unique<BumpedObject>(mesh, material));
            object.name = name;
            object.position = position;
            object.rotationDegrees = {0.0f, yawDegrees, 0.0f};
            object.scale = scale;
            object.normalMap = std::move(map);
        };
        // wall.obj spans x in [-4, 4], y in [0, 3], z in [-0.3, 0.3].
        add(m_floorMesh, ground, "floor", {0.0f, 0.0f, 0.0f}, 0.0f, {16.0f, 1.0f, 16.0f}, nullptr);
        add(m_wallMesh, m_wall.material, "wall", {-1.5f, 0.0f, -1.0f}, 0.0f, glm::vec3(0.5f), normalMap);
        add(m_mirroredMesh, m_wall.material, "mirrored wall", {1.9f, 0.0f, 0.0f}, -60.0f, glm::vec3(0.5f), normalMap);
        add(m_boulderMesh, stone, "boulder", {0.3f, 0.55f, 0.9f}, 30.0f, glm::vec3(1.1f), normalMap);
    }

    stoa::ModelPart m_wall;
    stoa::Image m_height;
    std::shared_ptr<const stoa::GpuMesh> m_wallMesh, m_mirroredMesh, m_boulderMesh, m_floorMesh;
    std::map<float, std::shared_ptr<const stoa::Texture2D>> m_normalMaps;
    std::optional<std::string> m_missing;  // the student function that has not run yet
    View m_view = View::Shaded;
    bool m_normalMapping = true;
    stoa::Scene m_scene;
    stoa::CameraRig m_cameras;
    stoa::ForwardRenderer m_renderer;
    stoa::Program* m_program = nullptr;
};

} // namespace

int main(int argc, char** argv) {
    NormalMappingLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
