// Lab 03 app: pieces of the Acropolis scene (assets/acropolis/) with the
// student's vertex normals (normals.cpp) and texture maps (textures.glsl),
// lit with the student's lab-02 Blinn-Phong through the lab-01 cameras.
//
// Case keys besides the camera's (CameraRig.hpp):
//   objects = NAME ...                   which pieces to show (kPieces below)
//   normals = smooth | facet | file      smoothNormals(), facetNormals(), or the
//                                        loader's (the file's, else area-weighted)
//   scale = x y z                        multiplies the scale of every piece but the floor
//   turn = degrees                       adds a turn about +Y to every piece but the floor
//   ambient = r g b                      scene ambient light
//   sun = dx dy dz  r g b                a directional light (omit for none)
//   point_light = x y z  r g b           a point light (omit for none)
//   attenuation = kc kl kq               for the point light
//
// Keys in the window: f switches between facet and smooth normals.

#include "checks.hpp"
#include "lab03.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/Scene.hpp>

#include <cstdio>
#include <iterator>
#include <map>
#include <sstream>

namespace {

/// Where a piece of the scene stands (world units: metres, +Y up).
struct Placement {
    const char* model;  // assets/acropolis/<model>.obj
    glm::vec3 position;
    float turnDegrees;  // about +Y
    glm::vec3 scale;
};

/// The pieces a case can name in `objects`, each one or more placed models.
const std::map<std::string, std::vector<Placement>> kPieces = {
    {"floor", {{"floor", {0.0f, 0.0f, 0.0f}, 0.0f, glm::vec3(1.0f)}}},
    {"statue", {{"statue", {0.0f, 0.0f, 0.0f}, 0.0f, glm::vec3(1.0f)}}},
    {"column", {{"column", {0.0f, 0.0f, 0.0f}, 0.0f, glm::vec3(1.0f)}}},
    {"columns",
     {{"column", {-3.5f, 0.0f, -3.0f}, 0.0f, glm::vec3(1.0f)},
      {"column", {0.0f, 0.0f, -3.0f}, 0.0f, glm::vec3(1.0f)},
      {"column", {3.5f, 0.0f, -3.0f}, 0.0f, glm::vec3(1.0f)}}},
    {"plinth", {{"plinth", {-1.1f, 0.0f, -0.3f}, 25.0f, glm::vec3(1.0f, 0.7f, 1.0f)}}},
    {"wall", {{"wall", {0.0f, 0.0f, -6.0f}, 0.0f, glm::vec3(1.0f)}}},
    {"temple", {{"temple", {0.0f, 0.0f, -14.0f}, 0.0f, glm::vec3(1.0f)}}},
};

/// A unit block (x and z in [-0.5, 0.5], y in [0, 1]) whose 8 corners are
/// shared by all 12 triangles, each face cut along a different diagonal: a
/// corner is used by one or two triangles of each face, so its smooth normal
/// shows how the triangles are weighted. (The OBJ models give every face its
/// own vertices where normals or uvs differ.)
stoa::Model plinthModel() {
    stoa::Mesh mesh;
    for (int i = 0; i < 8; ++i) {
        stoa::Vertex vertex;
        vertex.position = {(i & 1) ? 0.5f : -0.5f, (i & 2) ? 1.0f : 0.0f, (i & 4) ? 0.5f : -0.5f};
        mesh.vertices.push_back(vertex);
    }
    // Counter-clockwise seen from outside; corner i has bits x = 1, y = 2, z = 4.
    mesh.indices = {4, 5, 7, 4, 7, 6,   // +z: diagonal 4-7
                    1, 0, 2, 1, 2, 3,   // -z: diagonal 1-2
                    5, 1, 3, 5, 3, 7,   // +x: diagonal 5-3
                    0, 4, 6, 0, 6, 2,   // -x: diagonal 0-6
                    6, 7, 3, 6, 3, 2,   // +y: diagonal 6-3
                    0, 1, 5, 0, 5, 4};  // -y: diagonal 0-5
    stoa::computeSmoothNormals(mesh);   // replaced by the case's normal mode
    stoa::Material stone;
    stone.name = "plinth";
    stone.ambient = stone.diffuse = {0.55f, 0.5f, 0.45f};
    stone.specular = glm::vec3(0.3f);
    stone.shininess = 24.0f;
    stoa::Model model;
    model.parts.push_back({mesh, stone});
    model.source = "plinth (made in lab.cpp)";
    return model;
}

enum class NormalMode { Smooth, Facet, File };

class MeshesLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources& resources) override {
        m_program = &resources.loadProgram("textured/textured.vert", "textured/textured.frag");
    }

    void loadCase(const stoa::CaseSpec& spec) override {
        m_cameras.loadCase(spec);
        m_pieces = readPieces(spec);
        m_normals = readNormalMode(spec);
        m_scale = spec.getVec3("scale", glm::vec3(1.0f));
        m_turnDegrees = static_cast<float>(spec.getNumber("turn", 0.0));
        m_scene.ambient = spec.getVec3("ambient", glm::vec3(0.1f));
        m_scene.directionalLights.clear();
        m_scene.pointLights.clear();
        if (spec.has("sun")) {
            const std::vector<float> sun = spec.getNumbers("sun", 6, "direction x y z, colour r g b");
            m_scene.directionalLights.push_back({{sun[0], sun[1], sun[2]}, {sun[3], sun[4], sun[5]}});
        }
        if (spec.has("point_light")) {
            const std::vector<float> light = spec.getNumbers("point_light", 6, "position x y z, colour r g b");
            const glm::vec3 attenuation = spec.getVec3("attenuation", glm::vec3(1.0f, 0.09f, 0.032f));
            m_scene.pointLights.push_back(
                {{light[0], light[1], light[2]}, {light[3], light[4], light[5]}, attenuation});
        }
        buildScene();
    }

    void render(glm::ivec2 size) override { m_renderer.render(m_scene, m_cameras.active(), *m_program, size); }

    stoa::Camera& activeCamera() override { return m_cameras.active(); }
    void toggleCamera() override { m_cameras.toggle(); }

    stoa::CheckResult runCheck(const stoa::CaseSpec& spec) override {
        if (spec.check == "degenerate_triangles") return lab03::checkDegenerateTriangles();
        if (spec.check == "angle_weights") return lab03::checkAngleWeights();
        return Lab::runCheck(spec);
    }

    bool keyPressed(unsigned char key) override {
        if (key != 'f') return false;
        const NormalMode previous = m_normals;
        m_normals = m_normals == NormalMode::Facet ? NormalMode::Smooth : NormalMode::Facet;
        try {
            buildScene();
            std::printf("normals: %s\n", m_normals == NormalMode::Facet ? "facet" : "smooth");
        } catch (const stoa::NotImplemented& stub) {
            // The window keeps running on a stub: say which, keep the previous normals.
            std::printf("normals: %s is not implemented yet\n", stub.function().c_str());
            m_normals = previous;
            buildScene();
        }
        return true;
    }
    std::vector<std::string> keyHelp() const override { return {"f  switch between facet and smooth normals"}; }

private:
    static std::vector<std::string> readPieces(const stoa::CaseSpec& spec) {
        std::istringstream words(spec.getString("objects"));
        std::vector<std::string> pieces{std::istream_iterator<std::string>(words), {}};
        std::string known;
        for (const auto& entry : kPieces) known += " " + entry.first;
        if (pieces.empty()) spec.reject("objects", "objects names none of" + known);
        for (const std::string& piece : pieces) {
            if (!kPieces.count(piece)) spec.reject("objects", "objects: unknown piece '" + piece + "' (known:" + known + ")");
        }
        return pieces;
    }

    static NormalMode readNormalMode(const stoa::CaseSpec& spec) {
        const std::string mode = spec.getChoice("normals", {"smooth", "facet", "file"}, std::string("smooth"));
        if (mode == "facet") return NormalMode::Facet;
        if (mode == "file") return NormalMode::File;
        return NormalMode::Smooth;
    }

    /// The model's parts as loaded (CPU), read once per run.
    const stoa::Model& model(const std::string& name) {
        auto found = m_models.find(name);
        if (found == m_models.end()) {
            stoa::Model loaded = name == "plinth"
                                     ? plinthModel()
                                     : stoa::loadObj(stoa::paths::assetsDir() / "acropolis" / (name + ".obj"));
            found = m_models.emplace(name, std::move(loaded)).first;
        }
        return found->second;
    }

    /// The GPU meshes of a model's parts with the current normal mode, made once per mode.
    const std::vector<std::shared_ptr<const stoa::GpuMesh>>& gpuParts(const std::string& name) {
        const std::string key = name + "/" + std::to_string(static_cast<int>(m_normals));
        auto found = m_gpuParts.find(key);
        if (found != m_gpuParts.end()) return found->second;
        std::vector<std::shared_ptr<const stoa::GpuMesh>> parts;
        for (const stoa::ModelPart& part : model(name).parts) {
            stoa::Mesh mesh = part.mesh;
            if (m_normals == NormalMode::Facet) mesh = stoa::facetNormals(mesh);
            if (m_normals == NormalMode::Smooth) stoa::smoothNormals(mesh);
            parts.push_back(std::make_shared<const stoa::GpuMesh>(mesh));
        }
        return m_gpuParts.emplace(key, std::move(parts)).first->second;
    }

    /// Replaces the scene's objects, keeping its lights (Scene::clear() drops both).
    void buildScene() {
        const auto directionalLights = m_scene.directionalLights;
        const auto pointLights = m_scene.pointLights;
        m_scene.clear();
        m_scene.directionalLights = directionalLights;
        m_scene.pointLights = pointLights;
        for (const std::string& piece : m_pieces) {
            const bool isFloor = piece == "floor";
            for (const Placement& placement : kPieces.at(piece)) {
                const std::vector<stoa::ModelPart>& parts = model(placement.model).parts;
                const auto& meshes = gpuParts(placement.model);
                for (std::size_t i = 0; i < parts.size(); ++i) {
                    auto& object = m_scene.add(std::make_unique<stoa::MeshObject>(meshes[i], parts[i].material));
                    object.name = std::string(placement.model) + "/" + parts[i].material.name;
                    object.position = placement.position;
                    object.rotationDegrees = {0.0f, placement.turnDegrees + (isFloor ? 0.0f : m_turnDegrees), 0.0f};
                    object.scale = placement.scale * (isFloor ? glm::vec3(1.0f) : m_scale);
                }
            }
        }
    }

    stoa::Scene m_scene;
    stoa::CameraRig m_cameras;
    stoa::ForwardRenderer m_renderer;
    stoa::Program* m_program = nullptr;

    std::vector<std::string> m_pieces;
    NormalMode m_normals = NormalMode::Smooth;
    glm::vec3 m_scale{1.0f};
    float m_turnDegrees = 0.0f;
    std::map<std::string, stoa::Model> m_models;
    std::map<std::string, std::vector<std::shared_ptr<const stoa::GpuMesh>>> m_gpuParts;
};

} // namespace

int main(int argc, char** argv) {
    MeshesLab lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
