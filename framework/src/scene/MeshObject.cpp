#include <stoa/core/Assert.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/TextureCache.hpp>
#include <stoa/scene/MeshObject.hpp>

namespace stoa {

MeshObject::MeshObject(std::shared_ptr<const GpuMesh> mesh, Material material)
    : material(std::move(material)), m_mesh(std::move(mesh)) {
    STOA_ASSERT(m_mesh != nullptr, "MeshObject::MeshObject(): pass a mesh (std::make_shared<GpuMesh>(shapes::cube()))");
    resolveMaps();
}

void MeshObject::resolve(const std::string& path, ResolvedMap& map) {
    if (path.empty()) {
        map = {};
    } else if (map.path != path || !map.texture) {
        map = {path, TextureCache::shared().load(path)};
    }
}

void MeshObject::resolveMaps() {
    // Both loaded before anything is drawn: creating a texture binds it on
    // the active unit, which must not happen between binding maps and drawing.
    resolve(material.diffuseMap, m_diffuseMap);
    resolve(material.specularMap, m_specularMap);
}

std::optional<Bounds> MeshObject::localBounds() const { return m_mesh->bounds(); }

void MeshObject::addDraws(DrawList& list) const {
    STOA_ASSERT(material.diffuseMap == m_diffuseMap.path && material.specularMap == m_specularMap.path,
                "MeshObject::addDraws(): material.diffuseMap or specularMap changed after the object was made. "
                "Call resolveMaps() after changing them (maps load when the scene is built, not while drawing).");
    DrawItem item;
    item.mesh = m_mesh.get();
    item.model = modelMatrix();
    item.normalMatrix = normalMatrix();
    item.material = &material;
    item.diffuseMap = m_diffuseMap.texture.get();
    item.specularMap = m_specularMap.texture.get();
    item.object = this;
    list.push_back(item);
}

} // namespace stoa
