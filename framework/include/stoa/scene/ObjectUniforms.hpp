#pragma once
// The per-object uniforms of the framework's shaders, their locations looked
// up once per program, so that drawing an item sets them without a name
// lookup or a program switch (Program::setAt()).
//
//   program.use();
//   const ObjectUniforms uniforms(program);        // once per program
//   for (const DrawItem& item : list) { uniforms.apply(item); item.mesh->draw(); }
//
// The uniforms (those a shader does not declare are skipped): uModel,
// uNormalMatrix, uMaterial.{ambient,diffuse,specular,shininess},
// uDiffuseMap/uHasDiffuseMap on MeshObject::kDiffuseMapUnit,
// uSpecularMap/uHasSpecularMap on MeshObject::kSpecularMapUnit.

#include <stoa/gl/OpenGL.hpp>

namespace stoa {

class Program;
struct DrawItem;

class ObjectUniforms {
public:
    /// Looks the locations up in `program` (cached by the Program too).
    explicit ObjectUniforms(const Program& program);

    /// Sets the item's uniforms and binds its maps. `program` must be in use.
    void apply(const DrawItem& item) const;

    const Program& program() const { return *m_program; }

private:
    const Program* m_program;
    GLint m_model, m_normalMatrix;
    GLint m_ambient, m_diffuse, m_specular, m_shininess;
    GLint m_diffuseMap, m_hasDiffuseMap, m_specularMap, m_hasSpecularMap;
};

} // namespace stoa
