#include <stoa/geometry/Mesh.hpp>
#include <stoa/render/InstancedMesh.hpp>

#include <cstddef>

namespace stoa {

InstancedMesh::InstancedMesh(const Mesh& mesh) : m_mesh(mesh) {
    m_instances.upload(nullptr, sizeof(Instance), GL_DYNAMIC_DRAW);
    m_mesh.setInstanceAttributes(m_instances, sizeof(Instance), offsetof(Instance, model), offsetof(Instance, color));
}

void InstancedMesh::setInstances(const std::vector<Instance>& instances) {
    m_instances.upload(instances, GL_DYNAMIC_DRAW);
    m_count = instances.size();
}

void InstancedMesh::draw() const {
    if (m_count == 0) return;
    m_mesh.drawInstanced(static_cast<int>(m_count));
}

} // namespace stoa
