#include <stoa/geometry/Shapes.hpp>

#include <stoa/core/Assert.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>

namespace stoa::shapes {

namespace {

std::uint32_t indexOf(std::size_t vertexCount) { return static_cast<std::uint32_t>(vertexCount); }

void addTriangle(Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// Triangulates a grid of (columns + 1) x (rows + 1) vertices stored row by row,
// starting at `first`. The caller lays the grid out so that, seen from the
// front, columns grow to the right and rows grow downward (the row direction
// crossed with the column direction points to the front); each quad is then
// split into a-c-b and b-c-d, both counter-clockwise:
//
//   a --- b      row r
//   |   / |
//   | /   |
//   c --- d      row r + 1
void addGrid(Mesh& mesh, std::uint32_t first, int columns, int rows) {
    const std::uint32_t stride = static_cast<std::uint32_t>(columns) + 1;
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            const std::uint32_t a = first + static_cast<std::uint32_t>(row) * stride + static_cast<std::uint32_t>(column);
            const std::uint32_t b = a + 1, c = a + stride, d = c + 1;
            addTriangle(mesh, a, c, b);
            addTriangle(mesh, b, c, d);
        }
    }
}

} // namespace

Mesh plane(float size, int subdivisions) {
    STOA_ASSERT(size > 0.0f, "shapes::plane(): size must be positive.");
    STOA_ASSERT(subdivisions >= 1, "shapes::plane(): subdivisions must be at least 1.");
    Mesh mesh;
    // Row 0 is the far edge (z = -size/2, v = 1); seen from +Y with -Z at the
    // top, columns go right (+X) and rows go down (+Z), as addGrid expects.
    for (int row = 0; row <= subdivisions; ++row) {
        const float v = 1.0f - float(row) / float(subdivisions);
        for (int column = 0; column <= subdivisions; ++column) {
            const float u = float(column) / float(subdivisions);
            mesh.vertices.push_back({{(u - 0.5f) * size, 0.0f, (0.5f - v) * size}, {0.0f, 1.0f, 0.0f}, {u, v}});
        }
    }
    addGrid(mesh, 0, subdivisions, subdivisions);
    return mesh;
}

Mesh cube(float size) {
    STOA_ASSERT(size > 0.0f, "shapes::cube(): size must be positive.");
    // Each face is spanned by a right axis and an up axis with right x up =
    // normal, so corners listed as (-,-) (+,-) (+,+) (-,+) go counter-clockwise
    // seen from outside. Side faces keep +Y up; the top has -Z up and the
    // bottom +Z up, as if the cube were unfolded around its front face.
    struct Face { glm::vec3 normal, right, up; };
    const Face faces[6] = {
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},    // front  +Z
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},   // right  +X
        {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},  // back   -Z
        {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   // left   -X
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},   // top    +Y
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},   // bottom -Y
    };
    const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const float half = 0.5f * size;
    Mesh mesh;
    for (const Face& face : faces) {
        const std::uint32_t first = indexOf(mesh.vertices.size());
        for (const glm::vec2& uv : corners) {
            const glm::vec2 offset = 2.0f * uv - 1.0f;  // the corner in [-1, 1]^2 on the face
            const glm::vec3 position = half * (face.normal + offset.x * face.right + offset.y * face.up);
            mesh.vertices.push_back({position, face.normal, uv});
        }
        addTriangle(mesh, first, first + 1, first + 2);
        addTriangle(mesh, first, first + 2, first + 3);
    }
    return mesh;
}

// Spherical coordinates with the polar angle theta measured from +Y:
//   p = r (sin(theta) sin(phi), cos(theta), sin(theta) cos(phi))
// phi = 0 points at +Z and growing phi turns toward +X, so seen from outside
// u = phi / 2pi grows to the right and rings of growing theta go down: the
// layout addGrid expects. Each pole has one vertex per slice (same position,
// u in the middle of the slice) so that its triangle gets a sensible uv.
Mesh sphere(float radius, int slices, int stacks) {
    STOA_ASSERT(radius > 0.0f, "shapes::sphere(): radius must be positive.");
    STOA_ASSERT(slices >= 3 && stacks >= 2, "shapes::sphere(): use at least 3 slices and 2 stacks.");
    Mesh mesh;
    for (int stack = 0; stack <= stacks; ++stack) {
        const float theta = glm::pi<float>() * float(stack) / float(stacks);
        const float v = 1.0f - float(stack) / float(stacks);
        const bool pole = stack == 0 || stack == stacks;
        for (int slice = 0; slice <= slices; ++slice) {
            const float phi = glm::two_pi<float>() * float(slice % slices) / float(slices);  // the seam matches exactly
            glm::vec3 normal{std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
            if (pole) normal = {0.0f, stack == 0 ? 1.0f : -1.0f, 0.0f};
            mesh.vertices.push_back({radius * normal, normal, {float(slice) / float(slices), v}});
        }
    }
    // addGrid's quads, without the triangle that would collapse onto a pole.
    const std::uint32_t stride = static_cast<std::uint32_t>(slices) + 1;
    for (int stack = 0; stack < stacks; ++stack) {
        for (int slice = 0; slice < slices; ++slice) {
            const std::uint32_t a = static_cast<std::uint32_t>(stack) * stride + static_cast<std::uint32_t>(slice);
            const std::uint32_t b = a + 1, c = a + stride, d = c + 1;
            if (stack == 0) addTriangle(mesh, a, c, d);                // a and b are both the north pole
            else if (stack == stacks - 1) addTriangle(mesh, a, c, b);  // c and d are both the south pole
            else {
                addTriangle(mesh, a, c, b);
                addTriangle(mesh, b, c, d);
            }
        }
    }
    // A pole vertex serves one triangle, so its u is the middle of that
    // triangle's slice; the last one of each pole (u = 1) serves none.
    for (std::uint32_t slice = 0; slice < static_cast<std::uint32_t>(slices); ++slice) {
        const float u = (float(slice) + 0.5f) / float(slices);
        mesh.vertices[slice].uv.x = u;
        mesh.vertices[static_cast<std::uint32_t>(stacks) * stride + slice].uv.x = u;
    }
    return mesh;
}

Mesh cylinder(float radius, float height, int slices) {
    STOA_ASSERT(radius > 0.0f && height > 0.0f, "shapes::cylinder(): radius and height must be positive.");
    STOA_ASSERT(slices >= 3, "shapes::cylinder(): use at least 3 slices.");
    Mesh mesh;
    const float halfHeight = 0.5f * height;
    auto direction = [&](int slice) {  // unit vector in the XZ plane, +Z at slice 0, turning toward +X
        const float phi = glm::two_pi<float>() * float(slice % slices) / float(slices);
        return glm::vec3(std::sin(phi), 0.0f, std::cos(phi));
    };

    // The side: row 0 at the top, row 1 at the bottom, as in the sphere.
    for (int row = 0; row <= 1; ++row) {
        for (int slice = 0; slice <= slices; ++slice) {
            const glm::vec3 normal = direction(slice);
            const glm::vec3 position = radius * normal + glm::vec3(0.0f, row == 0 ? halfHeight : -halfHeight, 0.0f);
            mesh.vertices.push_back({position, normal, {float(slice) / float(slices), row == 0 ? 1.0f : 0.0f}});
        }
    }
    addGrid(mesh, 0, slices, 1);

    // The caps: a fan around a centre vertex. Their uvs are the cap seen from
    // outside, with +X to the right and the side's front (+Z) at the bottom of
    // the top cap and at the top of the bottom cap.
    for (float side : {1.0f, -1.0f}) {
        const glm::vec3 normal{0.0f, side, 0.0f};
        const std::uint32_t centre = indexOf(mesh.vertices.size());
        mesh.vertices.push_back({halfHeight * normal, normal, {0.5f, 0.5f}});
        for (int slice = 0; slice < slices; ++slice) {
            const glm::vec3 d = direction(slice);
            const glm::vec2 uv{0.5f + 0.5f * d.x, 0.5f - 0.5f * side * d.z};
            mesh.vertices.push_back({radius * d + halfHeight * normal, normal, uv});
        }
        for (int slice = 0; slice < slices; ++slice) {
            const std::uint32_t current = centre + 1 + static_cast<std::uint32_t>(slice);
            const std::uint32_t next = centre + 1 + static_cast<std::uint32_t>((slice + 1) % slices);
            // direction(slice) x direction(slice + 1) points along +Y.
            if (side > 0.0f) addTriangle(mesh, centre, current, next);
            else addTriangle(mesh, centre, next, current);
        }
    }
    return mesh;
}

// A point on the torus is its point on the tube's centre circle plus the tube normal:
//   radial = (sin(phi), 0, cos(phi)),  n = cos(theta) radial + sin(theta) Y,
//   p = R radial + r n
// At phi = theta = 0, the point (0, 0, R + r), growing phi moves along +X and
// growing theta along +Y, and X x Y = Z is the outward normal there. So rows
// of growing phi and columns of growing theta make the row direction crossed
// with the column direction point outward, as addGrid needs.
Mesh torus(float majorRadius, float minorRadius, int majorSegments, int minorSegments) {
    STOA_ASSERT(minorRadius > 0.0f && majorRadius > minorRadius,
                "shapes::torus(): need 0 < minorRadius < majorRadius (a ring torus).");
    STOA_ASSERT(majorSegments >= 3 && minorSegments >= 3, "shapes::torus(): use at least 3 segments each way.");
    Mesh mesh;
    for (int major = 0; major <= majorSegments; ++major) {
        const float u = float(major) / float(majorSegments);
        const float phi = glm::two_pi<float>() * float(major % majorSegments) / float(majorSegments);
        const glm::vec3 radial{std::sin(phi), 0.0f, std::cos(phi)};
        for (int minor = 0; minor <= minorSegments; ++minor) {
            const float v = float(minor) / float(minorSegments);
            const float theta = glm::two_pi<float>() * float(minor % minorSegments) / float(minorSegments);
            const glm::vec3 normal = std::cos(theta) * radial + glm::vec3(0.0f, std::sin(theta), 0.0f);
            mesh.vertices.push_back({majorRadius * radial + minorRadius * normal, normal, {u, v}});
        }
    }
    addGrid(mesh, 0, minorSegments, majorSegments);
    return mesh;
}

} // namespace stoa::shapes
