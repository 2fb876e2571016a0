#pragma once
// A Mesh uploaded to the GPU: its vertices, indices and the vertex array that
// ties them to the vertex shader's inputs.
//
//   layout(location = 0) in vec3 aPosition;   // object space
//   layout(location = 1) in vec3 aNormal;     // object space
//   layout(location = 2) in vec2 aUv;
//   layout(location = 3) in vec4 aTangent;    // object space; w = handedness (+-1)
//
//   GpuMesh cube(shapes::cube(1.0f));
//   program.use();
//   cube.draw();

#include <stoa/geometry/Bounds.hpp>
#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/VertexArray.hpp>

#include <cstddef>

namespace stoa {

class Mesh;

class GpuMesh {
public:
    /// Attribute locations every Stoa vertex shader uses.
    static constexpr GLuint kPositionLocation = 0; // vec3
    static constexpr GLuint kNormalLocation = 1;   // vec3
    static constexpr GLuint kUvLocation = 2;       // vec2
    static constexpr GLuint kTangentLocation = 3;  // vec4: xyz tangent, w handedness (Vertex::tangent)

    /// Uploads `mesh` (a copy: the Mesh may go away). Needs a current context.
    /// A mesh without indices is drawn as a plain triangle list.
    explicit GpuMesh(const Mesh& mesh);

    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;
    GpuMesh(GpuMesh&&) noexcept = default;
    GpuMesh& operator=(GpuMesh&&) noexcept = default;

    /// Draws every triangle with the program in use. Leaves the vertex array bound.
    void draw() const;
    /// Draws `instances` copies (gl_InstanceID 0 .. instances-1).
    void drawInstanced(int instances) const;

    std::size_t indexCount() const { return m_indexCount; }  // 3 per triangle; 0 without indices
    std::size_t vertexCount() const { return m_vertexCount; }
    /// The mesh's box and sphere in object space (boundsOf(), kept from the upload).
    const Bounds& bounds() const { return m_bounds; }

    /// Per-instance attributes for drawInstanced(), advanced once per instance:
    /// a mat4 model matrix (locations 4-7, one column each) and a vec4 colour
    /// (location 8), `stride` bytes apart in `instances`, from `offset`. The
    /// buffer must outlive the draws (InstancedMesh keeps both together).
    static constexpr GLuint kInstanceModelLocation = 4;   // 4, 5, 6, 7
    static constexpr GLuint kInstanceColorLocation = 8;
    void setInstanceAttributes(const Buffer& instances, std::size_t stride, std::size_t modelOffset,
                               std::size_t colorOffset);

private:
    VertexArray m_vertexArray;
    Buffer m_vertices{GL_ARRAY_BUFFER};
    Buffer m_indices{GL_ELEMENT_ARRAY_BUFFER};
    std::size_t m_indexCount = 0;
    std::size_t m_vertexCount = 0;
    Bounds m_bounds;
};

} // namespace stoa
