#pragma once
// Acropolis pieces (AcropolisScene.hpp) uploaded and ready to draw: one
// DrawItem per piece, with its mesh (each distinct mesh uploaded once), its
// material and its textures, held for as long as this object lives. For the
// labs that draw the scene through a renderer of their own (labs 08-09).
//
//   PieceDrawList scene(acropolisPieces());   // needs a current context
//   renderer.render(scene.items(), ...);

#include <stoa/geometry/Material.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/DrawList.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace stoa {

class GpuMesh;
class Texture2D;

class PieceDrawList {
public:
    /// Uploads the pieces' meshes and loads their diffuse and specular maps
    /// (TextureCache). Throws InputError when a texture file is missing or broken.
    explicit PieceDrawList(const std::vector<AcropolisPiece>& pieces);
    ~PieceDrawList();

    PieceDrawList(const PieceDrawList&) = delete;
    PieceDrawList& operator=(const PieceDrawList&) = delete;

    const DrawList& items() const { return m_items; }
    std::size_t triangleCount() const { return m_triangles; }

private:
    std::vector<std::shared_ptr<GpuMesh>> m_meshes;
    std::vector<std::unique_ptr<Material>> m_materials;
    std::vector<std::shared_ptr<const Texture2D>> m_textures;
    DrawList m_items;
    std::size_t m_triangles = 0;
};

} // namespace stoa
