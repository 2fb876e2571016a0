#include <stoa/scene/AcropolisScene.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/GpuResources.hpp>
#include <stoa/scene/MeshObject.hpp>

#include <glm/common.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <limits>

#include <map>
#include <memory>
#include <vector>

namespace stoa {

namespace {

// Where one object goes. `file` empty means the pedestal (a procedural cube).
struct Placement {
    std::string file;
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 rotationDegrees{0.0f};
    glm::vec3 scale{1.0f};
};

constexpr float kPedestalHeight = 1.2f;  // metres; the statue stands on top

std::vector<Placement> layout(const AcropolisOptions& options) {
    STOA_ASSERT(options.columnCount >= 1 && options.columnCount <= 12,
                "buildAcropolisScene(): AcropolisOptions::columnCount must be 1..12 (set columns = false for none)");
    std::vector<Placement> placements;
    if (options.floor) placements.push_back({"floor.obj", "floor", {0.0f, 0.0f, 0.0f}, {}, glm::vec3(1.0f)});
    if (options.temple) placements.push_back({"temple.obj", "temple", {0.0f, 0.0f, -8.5f}, {}, glm::vec3(1.0f)});
    if (options.columns) {
        for (int i = 0; i < options.columnCount; ++i) {
            const float x = 2.5f * (static_cast<float>(i) - 0.5f * static_cast<float>(options.columnCount - 1));
            placements.push_back({"column.obj", "column " + std::to_string(i + 1), {x, 0.0f, -1.5f}, {}, glm::vec3(1.0f)});
        }
    }
    // Turned so that its front (+Z in the file) faces +X, the scene's centre.
    if (options.wall) placements.push_back({"wall.obj", "wall", {-10.0f, 0.0f, -3.0f}, {0.0f, 90.0f, 0.0f}, glm::vec3(1.0f)});
    if (options.statue) {
        placements.push_back({"", "pedestal", {6.5f, 0.5f * kPedestalHeight, 3.0f}, {0.0f, -20.0f, 0.0f}, {1.0f, kPedestalHeight, 1.0f}});
        placements.push_back({"statue.obj", "statue", {6.5f, kPedestalHeight, 3.0f}, {0.0f, -20.0f, 0.0f}, glm::vec3(1.0f)});
    }
    return placements;
}

std::filesystem::path assetPath(const std::string& fileName) { return paths::assetsDir() / "acropolis" / fileName; }

// The pedestal: a unit cube (centred, side 1) in the column's marble.
const Mesh& pedestalMesh() {
    static const Mesh cube = shapes::cube(1.0f);
    return cube;
}
const Material& pedestalMaterial() { return acropolisModel("column.obj").parts.front().material; }

// Meshes uploaded without a filter, shared by every build in this context
// while some scene still draws them. Weak, so that once the last scene lets go
// the next build uploads afresh; one map per context (GpuResources), so that a
// new context never draws a mesh of the last one.
struct UploadedMeshes {
    std::map<std::string, std::weak_ptr<const GpuMesh>> byName;
};

std::map<std::string, std::weak_ptr<const GpuMesh>>& uploadedMeshes() {
    return GpuResources::current().cache<UploadedMeshes>().byName;
}

std::size_t& uploads() {
    static std::size_t count = 0;
    return count;
}

} // namespace

std::size_t acropolisUploadCount() { return uploads(); }

const Model& acropolisModel(const std::string& fileName) {
    static std::map<std::string, Model> models;
    auto found = models.find(fileName);
    if (found == models.end()) found = models.emplace(fileName, loadObj(assetPath(fileName))).first;
    return found->second;
}

DirectionalLight acropolisSun() {
    DirectionalLight sun;
    sun.direction = glm::vec3(-0.45f, -0.5f, -0.75f);  // travelling down, left and away from the camera
    sun.color = glm::vec3(1.0f, 0.93f, 0.82f);
    return sun;
}

void buildAcropolisScene(Scene& scene, const AcropolisOptions& options) {
    const std::vector<Placement> placements = layout(options);

    // Gather (and upload where needed) every mesh before clearing the scene, so
    // that the meshes its old objects hold are reused rather than released.
    std::map<std::string, std::shared_ptr<const GpuMesh>> meshes;
    auto upload = [&](const std::string& key, const Mesh& mesh) {
        if (meshes.count(key)) return;
        if (options.meshFilter) {
            ++uploads();
            meshes[key] = std::make_shared<const GpuMesh>(options.meshFilter(mesh));
            return;
        }
        std::shared_ptr<const GpuMesh> shared = uploadedMeshes()[key].lock();
        if (!shared) {
            ++uploads();
            shared = std::make_shared<const GpuMesh>(mesh);
            uploadedMeshes()[key] = shared;
        }
        meshes[key] = shared;
    };
    for (const Placement& placement : placements) {
        if (placement.file.empty()) {
            upload("pedestal", pedestalMesh());
            continue;
        }
        const Model& model = acropolisModel(placement.file);
        for (std::size_t part = 0; part < model.parts.size(); ++part)
            upload(placement.file + "#" + std::to_string(part), model.parts[part].mesh);
    }

    scene.clear();
    scene.ambient = glm::vec3(0.15f);
    scene.directionalLights.push_back(acropolisSun());
    for (const Placement& placement : placements) {
        auto place = [&](const std::string& key, const Material& material) {
            MeshObject& object = scene.add(std::make_unique<MeshObject>(meshes.at(key), material));
            object.name = placement.name;
            object.position = placement.position;
            object.rotationDegrees = placement.rotationDegrees;
            object.scale = placement.scale;
        };
        if (placement.file.empty()) {
            place("pedestal", pedestalMaterial());
            continue;
        }
        const Model& model = acropolisModel(placement.file);
        for (std::size_t part = 0; part < model.parts.size(); ++part)
            place(placement.file + "#" + std::to_string(part), model.parts[part].material);
    }
}

namespace {

// Object::modelMatrix()'s order (scale, then X, Y, Z rotations, then translation),
// written out here so that what needs no GL does not depend on the lab-01 code being built.
glm::mat4 modelOf(const Placement& placement) {
    glm::mat4 model = glm::translate(glm::mat4(1.0f), placement.position);
    model = glm::rotate(model, glm::radians(placement.rotationDegrees.z), {0.0f, 0.0f, 1.0f});
    model = glm::rotate(model, glm::radians(placement.rotationDegrees.y), {0.0f, 1.0f, 0.0f});
    model = glm::rotate(model, glm::radians(placement.rotationDegrees.x), {1.0f, 0.0f, 0.0f});
    return glm::scale(model, placement.scale);
}

} // namespace

std::vector<AcropolisPiece> acropolisPieces(const AcropolisOptions& options) {
    std::vector<AcropolisPiece> pieces;
    for (const Placement& placement : layout(options)) {
        const glm::mat4 model = modelOf(placement);
        if (placement.file.empty()) {
            pieces.push_back({placement.name, &pedestalMesh(), pedestalMaterial(), model});
            continue;
        }
        for (const ModelPart& part : acropolisModel(placement.file).parts)
            pieces.push_back({placement.name, &part.mesh, part.material, model});
    }
    return pieces;
}

std::vector<AcropolisPiece> acropolisAvenuePieces() {
    std::vector<AcropolisPiece> pieces = acropolisPieces();
    const std::size_t original = pieces.size();
    for (int i = 0; i < 6; ++i) {
        const float side = i % 2 == 0 ? -1.0f : 1.0f;
        const glm::vec3 place(side * 3.2f, 0.0f, 2.0f + 3.5f * static_cast<float>(i / 2));
        const float turn = side > 0.0f ? -90.0f : 90.0f;   // facing the path
        const glm::mat4 base = glm::rotate(glm::translate(glm::mat4(1.0f), place), glm::radians(turn), glm::vec3(0, 1, 0));
        const std::string name = "statue " + std::to_string(i + 2);
        pieces.push_back({name, &pedestalMesh(), pedestalMaterial(),
                          glm::scale(glm::translate(base, glm::vec3(0.0f, 0.4f, 0.0f)), glm::vec3(0.9f, 0.8f, 0.9f))});
        for (std::size_t k = 0; k < original; ++k)
            if (pieces[k].name == "statue")
                pieces.push_back({name, pieces[k].mesh, pieces[k].material, glm::translate(base, glm::vec3(0.0f, 0.8f, 0.0f))});
    }
    return pieces;
}

std::pair<glm::vec3, glm::vec3> acropolisBounds(const AcropolisOptions& options) {
    glm::vec3 lower(std::numeric_limits<float>::max()), upper(std::numeric_limits<float>::lowest());
    for (const AcropolisPiece& piece : acropolisPieces(options)) {
        // The 8 corners of the object-space box bound the transformed mesh.
        const auto [boxLower, boxUpper] = piece.mesh->bounds();
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 local((corner & 1) ? boxUpper.x : boxLower.x, (corner & 2) ? boxUpper.y : boxLower.y,
                                  (corner & 4) ? boxUpper.z : boxLower.z);
            const glm::vec3 world(piece.model * glm::vec4(local, 1.0f));
            lower = glm::min(lower, world);
            upper = glm::max(upper, world);
        }
    }
    STOA_ASSERT(lower.x <= upper.x, "acropolisBounds(): the options include no object; enable at least one");
    return {lower, upper};
}

} // namespace stoa
