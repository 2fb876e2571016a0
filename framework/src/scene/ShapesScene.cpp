#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/ShapesScene.hpp>

namespace stoa {

namespace {

Material makeMaterial(const char* name, glm::vec3 diffuse, glm::vec3 specular, float shininess) {
    Material material;
    material.name = name;
    material.ambient = diffuse;
    material.diffuse = diffuse;
    material.specular = specular;
    material.shininess = shininess;
    return material;
}

MeshObject& place(Scene& scene, const std::shared_ptr<const GpuMesh>& mesh, const Material& material,
                  const char* name, glm::vec3 position, glm::vec3 rotationDegrees, glm::vec3 scale) {
    MeshObject& object = scene.add(std::make_unique<MeshObject>(mesh, material));
    object.name = name;
    object.position = position;
    object.rotationDegrees = rotationDegrees;
    object.scale = scale;
    return object;
}

} // namespace

void buildShapesScene(Scene& scene) {
    scene.clear();
    // The meshes live as long as the objects that share them.
    const auto plane = std::make_shared<const GpuMesh>(shapes::plane(1.0f, 8));
    const auto cube = std::make_shared<const GpuMesh>(shapes::cube(1.0f));
    const auto sphere = std::make_shared<const GpuMesh>(shapes::sphere(0.5f, 48, 24));
    const auto cylinder = std::make_shared<const GpuMesh>(shapes::cylinder(0.5f, 1.0f, 48));
    const auto torus = std::make_shared<const GpuMesh>(shapes::torus(0.4f, 0.15f, 64, 32));

    const Material floor = makeMaterial("floor", {0.55f, 0.55f, 0.52f}, {0.1f, 0.1f, 0.1f}, 8.0f);
    const Material brick = makeMaterial("brick", {0.75f, 0.28f, 0.18f}, {0.3f, 0.3f, 0.3f}, 16.0f);
    const Material marble = makeMaterial("marble", {0.85f, 0.82f, 0.75f}, {0.9f, 0.9f, 0.9f}, 96.0f);
    const Material bronze = makeMaterial("bronze", {0.62f, 0.45f, 0.2f}, {0.8f, 0.7f, 0.5f}, 48.0f);
    const Material teal = makeMaterial("teal", {0.15f, 0.55f, 0.6f}, {0.5f, 0.5f, 0.5f}, 32.0f);
    const Material plum = makeMaterial("plum", {0.5f, 0.25f, 0.55f}, {0.6f, 0.6f, 0.6f}, 64.0f);

    place(scene, plane, floor, "floor", {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {10.0f, 1.0f, 10.0f});
    place(scene, cube, brick, "cube", {-2.0f, 0.5f, 0.5f}, {0.0f, 30.0f, 0.0f}, {1.0f, 1.0f, 1.0f});
    place(scene, cylinder, teal, "cylinder", {0.0f, 0.75f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.8f, 1.5f, 0.8f});
    place(scene, cube, plum, "small cube", {2.1f, 0.35f, 0.9f}, {0.0f, 20.0f, 35.0f}, {0.5f, 0.5f, 0.5f});
    place(scene, sphere, marble, "sphere", {1.4f, 0.7f, -1.2f}, {0.0f, 0.0f, 0.0f}, {1.4f, 1.0f, 1.4f});
    place(scene, torus, bronze, "torus", {-1.1f, 1.3f, -1.6f}, {60.0f, 0.0f, 20.0f}, {1.6f, 1.6f, 1.6f});
}

} // namespace stoa
