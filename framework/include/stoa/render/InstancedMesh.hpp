#pragma once
// Many copies of one mesh in one draw call: each instance has its own model
// matrix and colour, read by the vertex shader as per-instance attributes
// (shaders/instanced/instanced.vert: locations 4-7 the matrix's columns, 8 the
// colour). For crowds and fields of objects (lab 10), where one draw per
// object would cost more CPU time than the drawing (tests/benchmarks/
// instancing_benchmark.cpp has the figures).
//
//   InstancedMesh agents(shapes::sphere(0.5f, 18, 15));   // needs a current context
//   agents.setInstances(instances);                       // each frame the agents move
//   program.use();
//   agents.draw();

#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/GpuMesh.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace stoa {

class Mesh;

/// One copy: where it is and its colour.
struct Instance {
    glm::mat4 model{1.0f};       // object -> world; normals use its 3x3 (uniform scales)
    glm::vec4 color{1.0f};       // linear RGB, alpha
};
static_assert(sizeof(Instance) == 20 * sizeof(float), "Instance is uploaded as 20 tightly packed floats");

class InstancedMesh {
public:
    /// Uploads `mesh`. No instances yet.
    explicit InstancedMesh(const Mesh& mesh);

    /// Replaces the instances (one upload).
    void setInstances(const std::vector<Instance>& instances);
    /// Draws every instance with the program in use.
    void draw() const;

    std::size_t instanceCount() const { return m_count; }
    const GpuMesh& mesh() const { return m_mesh; }

private:
    GpuMesh m_mesh;
    Buffer m_instances{GL_ARRAY_BUFFER};
    std::size_t m_count = 0;
};

} // namespace stoa
