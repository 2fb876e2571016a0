#pragma once
// An Object drawn as a triangle mesh with a Blinn-Phong material.

#include <stoa/geometry/Material.hpp>
#include <stoa/scene/Object.hpp>

#include <memory>

namespace stoa {

class GpuMesh;

class MeshObject : public Object {
public:
    /// The mesh is shared: many objects may draw the same GpuMesh.
    explicit MeshObject(std::shared_ptr<const GpuMesh> mesh, Material material = {});

    Material material;

    /// Sets uModel, uNormalMatrix, uMaterial.{ambient,diffuse,specular,shininess} and draws.
    void draw(const Program& program) const override;

private:
    std::shared_ptr<const GpuMesh> m_mesh;
};

} // namespace stoa
