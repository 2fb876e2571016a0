#pragma once
// The scene as data for a renderer: one DrawItem per mesh to draw, with its
// matrices and its resolved material, built once per frame from the objects
// (Object::addDraws()). A renderer filters it (culling), sorts it, and draws
// it with its own program; objects never set uniforms by name per frame.
//
//   DrawList list = buildDrawList(scene);
//   for (const DrawItem& item : list) { uniforms.apply(item); item.mesh->draw(); }

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <vector>

namespace stoa {

class GpuMesh;
class Object;
class Scene;
class Texture2D;
struct Material;

struct DrawItem {
    const GpuMesh* mesh = nullptr;
    glm::mat4 model{1.0f};           // object -> world
    glm::mat3 normalMatrix{1.0f};    // the inverse transpose of model's upper 3x3
    const Material* material = nullptr;     // nullptr: no material uniforms
    const Texture2D* diffuseMap = nullptr;  // resolved when the scene was built; nullptr: none
    const Texture2D* specularMap = nullptr;
    const Object* object = nullptr;  // who added it: Object::setDrawUniforms() runs before it draws
};

using DrawList = std::vector<DrawItem>;

/// Every object's draw items, in the scene's order. Runs the objects' code
/// (model matrices: lab 01's modelMatrix()), so a stub throws from here.
DrawList buildDrawList(const Scene& scene);

} // namespace stoa
