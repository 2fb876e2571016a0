#include <stoa/core/Assert.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/TextureCache.hpp>
#include <stoa/scene/MeshObject.hpp>

namespace stoa {

MeshObject::MeshObject(std::shared_ptr<const GpuMesh> mesh, Material material)
    : material(std::move(material)), m_mesh(std::move(mesh)) {
    STOA_ASSERT(m_mesh != nullptr, "MeshObject::MeshObject(): pass a mesh (std::make_shared<GpuMesh>(shapes::cube()))");
}

void MeshObject::refreshMap(const std::string& path, BoundMap& map) {
    if (path.empty()) {
        map = {};
    } else if (map.path != path || !map.texture) {
        map = {path, TextureCache::shared().load(path)};
    }
}

void MeshObject::bindMap(const Program& program, const BoundMap& map, int unit, const char* sampler,
                         const char* flag) {
    // The sampler gets its unit even without a map, so that two samplers of
    // different types never share unit 0 (a draw error in GL 3.3).
    program.set(sampler, unit);
    program.set(flag, map.texture != nullptr);
    if (map.texture) map.texture->bind(unit);
}

void MeshObject::draw(const Program& program) const {
    program.set("uModel", modelMatrix());
    program.set("uNormalMatrix", normalMatrix());
    program.set("uMaterial.ambient", material.ambient);
    program.set("uMaterial.diffuse", material.diffuse);
    program.set("uMaterial.specular", material.specular);
    program.set("uMaterial.shininess", material.shininess);
    refreshMap(material.diffuseMap, m_diffuseMap);
    refreshMap(material.specularMap, m_specularMap);
    bindMap(program, m_diffuseMap, kDiffuseMapUnit, "uDiffuseMap", "uHasDiffuseMap");
    bindMap(program, m_specularMap, kSpecularMapUnit, "uSpecularMap", "uHasSpecularMap");
    m_mesh->draw();
}

} // namespace stoa
