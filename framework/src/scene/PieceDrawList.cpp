#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/TextureCache.hpp>
#include <stoa/scene/PieceDrawList.hpp>

#include <glm/gtc/matrix_inverse.hpp>

#include <map>

namespace stoa {

PieceDrawList::PieceDrawList(const std::vector<AcropolisPiece>& pieces) {
    std::map<const Mesh*, std::shared_ptr<GpuMesh>> uploaded;
    for (const AcropolisPiece& piece : pieces) {
        std::shared_ptr<GpuMesh>& mesh = uploaded[piece.mesh];
        if (!mesh) {
            mesh = std::make_shared<GpuMesh>(*piece.mesh);
            m_meshes.push_back(mesh);
        }
        m_materials.push_back(std::make_unique<Material>(piece.material));
        DrawItem item;
        item.mesh = mesh.get();
        item.model = piece.model;
        item.normalMatrix = glm::inverseTranspose(glm::mat3(piece.model));
        item.material = m_materials.back().get();
        if (!piece.material.diffuseMap.empty()) {
            m_textures.push_back(TextureCache::shared().load(piece.material.diffuseMap));
            item.diffuseMap = m_textures.back().get();
        }
        if (!piece.material.specularMap.empty()) {
            m_textures.push_back(TextureCache::shared().load(piece.material.specularMap));
            item.specularMap = m_textures.back().get();
        }
        m_items.push_back(item);
        m_triangles += piece.mesh->triangleCount();
    }
}

PieceDrawList::~PieceDrawList() = default;

} // namespace stoa
