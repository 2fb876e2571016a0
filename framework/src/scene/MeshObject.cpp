#include <stoa/core/Assert.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/scene/MeshObject.hpp>

namespace stoa {

MeshObject::MeshObject(std::shared_ptr<const GpuMesh> mesh, Material material)
    : material(std::move(material)), m_mesh(std::move(mesh)) {
    STOA_ASSERT(m_mesh != nullptr, "MeshObject::MeshObject(): pass a mesh (std::make_shared<GpuMesh>(shapes::cube()))");
}

void MeshObject::draw(const Program& program) const {
    program.set("uModel", modelMatrix());
    program.set("uNormalMatrix", normalMatrix());
    program.set("uMaterial.ambient", material.ambient);
    program.set("uMaterial.diffuse", material.diffuse);
    program.set("uMaterial.specular", material.specular);
    program.set("uMaterial.shininess", material.shininess);
    m_mesh->draw();
}

} // namespace stoa
