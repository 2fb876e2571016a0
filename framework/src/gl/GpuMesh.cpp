#include <stoa/gl/GpuMesh.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/geometry/Mesh.hpp>
#include <stoa/gl/Debug.hpp>

#include <cstddef>

namespace stoa {

GpuMesh::GpuMesh(const Mesh& mesh)
    : m_indexCount(mesh.indices.size()), m_vertexCount(mesh.vertices.size()), m_bounds(boundsOf(mesh)) {
    m_vertices.upload(mesh.vertices);
    m_vertexArray.attribute(kPositionLocation, m_vertices, 3, GL_FLOAT, sizeof(Vertex), offsetof(Vertex, position));
    m_vertexArray.attribute(kNormalLocation, m_vertices, 3, GL_FLOAT, sizeof(Vertex), offsetof(Vertex, normal));
    m_vertexArray.attribute(kUvLocation, m_vertices, 2, GL_FLOAT, sizeof(Vertex), offsetof(Vertex, uv));
    m_vertexArray.attribute(kTangentLocation, m_vertices, 4, GL_FLOAT, sizeof(Vertex), offsetof(Vertex, tangent));
    if (m_indexCount > 0) {
        m_indices.upload(mesh.indices);
        m_vertexArray.elementBuffer(m_indices);
    }
    VertexArray::unbind();
}

void GpuMesh::draw() const { drawInstanced(1); }

void GpuMesh::setInstanceAttributes(const Buffer& instances, std::size_t stride, std::size_t modelOffset,
                                    std::size_t colorOffset) {
    for (GLuint column = 0; column < 4; ++column) {
        const GLuint location = kInstanceModelLocation + column;
        m_vertexArray.attribute(location, instances, 4, GL_FLOAT, stride, modelOffset + column * 4 * sizeof(float));
        m_vertexArray.divisor(location, 1);
    }
    m_vertexArray.attribute(kInstanceColorLocation, instances, 4, GL_FLOAT, stride, colorOffset);
    m_vertexArray.divisor(kInstanceColorLocation, 1);
    VertexArray::unbind();
}

void GpuMesh::drawInstanced(int instances) const {
    STOA_ASSERT(m_vertexArray.id() != 0, "GpuMesh::draw(): the mesh was moved from. Draw the GpuMesh it moved to.");
    m_vertexArray.bind();
    const auto vertices = static_cast<GLsizei>(m_vertexCount);
    const auto indices = static_cast<GLsizei>(m_indexCount);
    if (instances == 1) {
        if (m_indexCount > 0)
            STOA_GL_CALL(glDrawElements(GL_TRIANGLES, indices, GL_UNSIGNED_INT, nullptr));
        else
            STOA_GL_CALL(glDrawArrays(GL_TRIANGLES, 0, vertices));
    } else if (m_indexCount > 0) {
        STOA_GL_CALL(glDrawElementsInstanced(GL_TRIANGLES, indices, GL_UNSIGNED_INT, nullptr, instances));
    } else {
        STOA_GL_CALL(glDrawArraysInstanced(GL_TRIANGLES, 0, vertices, instances));
    }
}

} // namespace stoa
