#include <stoa/geometry/Material.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/Texture2D.hpp>
#include <stoa/scene/DrawList.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/ObjectUniforms.hpp>

namespace stoa {

ObjectUniforms::ObjectUniforms(const Program& program)
    : m_program(&program),
      m_model(program.uniformLocation("uModel")),
      m_normalMatrix(program.uniformLocation("uNormalMatrix")),
      m_ambient(program.uniformLocation("uMaterial.ambient")),
      m_diffuse(program.uniformLocation("uMaterial.diffuse")),
      m_specular(program.uniformLocation("uMaterial.specular")),
      m_shininess(program.uniformLocation("uMaterial.shininess")),
      m_diffuseMap(program.uniformLocation("uDiffuseMap")),
      m_hasDiffuseMap(program.uniformLocation("uHasDiffuseMap")),
      m_specularMap(program.uniformLocation("uSpecularMap")),
      m_hasSpecularMap(program.uniformLocation("uHasSpecularMap")) {}

void ObjectUniforms::apply(const DrawItem& item) const {
    const Program& program = *m_program;
    if (item.object) item.object->setDrawUniforms(program);
    program.setAt(m_model, item.model);
    program.setAt(m_normalMatrix, item.normalMatrix);
    if (!item.material) return;
    program.setAt(m_ambient, item.material->ambient);
    program.setAt(m_diffuse, item.material->diffuse);
    program.setAt(m_specular, item.material->specular);
    program.setAt(m_shininess, item.material->shininess);
    // The samplers get their units even without a map, so that two samplers
    // of different types never share unit 0 (a draw error in GL 3.3).
    program.setAt(m_diffuseMap, MeshObject::kDiffuseMapUnit);
    program.setAt(m_hasDiffuseMap, item.diffuseMap != nullptr);
    if (item.diffuseMap) item.diffuseMap->bind(MeshObject::kDiffuseMapUnit);
    program.setAt(m_specularMap, MeshObject::kSpecularMapUnit);
    program.setAt(m_hasSpecularMap, item.specularMap != nullptr);
    if (item.specularMap) item.specularMap->bind(MeshObject::kSpecularMapUnit);
}

} // namespace stoa
