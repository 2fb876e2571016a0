#include "Geometry.hpp"

#include "Noise.hpp"
#include "PortableMath.hpp"

#include <stoa/core/Assert.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <array>
#include <cmath>
#include <functional>

namespace stoa::assets {

namespace {

constexpr float kTwoPi = glm::two_pi<float>();

// The generated files must not depend on the C library's rounding (PortableMath.hpp).
float sine(float x) { return static_cast<float>(portableSin(x)); }
float cosine(float x) { return static_cast<float>(portableCos(x)); }

void append(Mesh& target, const Mesh& piece) {
    const auto offset = static_cast<std::uint32_t>(target.vertices.size());
    target.vertices.insert(target.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (std::uint32_t index : piece.indices) target.indices.push_back(offset + index);
}

Vertex vertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv) {
    Vertex v;
    v.position = position;
    v.normal = normal;
    v.uv = uv;
    return v;
}

// A flat polygon (3 or 4 corners, counter-clockwise seen from its front) with
// its own vertices, so its edges stay sharp. The uvs are planar: u along the
// first edge, v along the last, `metresPerRepeat` metres per texture repeat,
// measured from the world origin so that neighbouring faces line up.
void addFlat(Mesh& mesh, const std::vector<glm::vec3>& corners, float metresPerRepeat) {
    const glm::vec3 uAxis = glm::normalize(corners[1] - corners[0]);
    const glm::vec3 normal = glm::normalize(glm::cross(corners[1] - corners[0], corners.back() - corners[0]));
    const glm::vec3 vAxis = glm::cross(normal, uAxis);
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const glm::vec3& p : corners)
        mesh.vertices.push_back(vertex(p, normal, glm::vec2(glm::dot(p, uAxis), glm::dot(p, vAxis)) / metresPerRepeat));
    for (std::uint32_t k = 1; k + 1 < corners.size(); ++k) {
        mesh.indices.push_back(first);
        mesh.indices.push_back(first + k);
        mesh.indices.push_back(first + k + 1);
    }
}

// An axis-aligned box from `lower` to `upper`: 24 vertices, 12 triangles.
void addBox(Mesh& mesh, glm::vec3 lower, glm::vec3 upper, float metresPerRepeat) {
    const glm::vec3 l = lower, u = upper;
    addFlat(mesh, {{l.x, l.y, u.z}, {u.x, l.y, u.z}, {u.x, u.y, u.z}, {l.x, u.y, u.z}}, metresPerRepeat);  // +Z
    addFlat(mesh, {{u.x, l.y, l.z}, {l.x, l.y, l.z}, {l.x, u.y, l.z}, {u.x, u.y, l.z}}, metresPerRepeat);  // -Z
    addFlat(mesh, {{u.x, l.y, u.z}, {u.x, l.y, l.z}, {u.x, u.y, l.z}, {u.x, u.y, u.z}}, metresPerRepeat);  // +X
    addFlat(mesh, {{l.x, l.y, l.z}, {l.x, l.y, u.z}, {l.x, u.y, u.z}, {l.x, u.y, l.z}}, metresPerRepeat);  // -X
    addFlat(mesh, {{l.x, u.y, u.z}, {u.x, u.y, u.z}, {u.x, u.y, l.z}, {l.x, u.y, l.z}}, metresPerRepeat);  // +Y
    addFlat(mesh, {{l.x, l.y, l.z}, {u.x, l.y, l.z}, {u.x, l.y, u.z}, {l.x, l.y, u.z}}, metresPerRepeat);  // -Y
}

// A surface around the Y axis: rings x slices positions from `position(ring,
// slice)`, slice 0 at +Z turning towards +X. Smooth normals are computed on the
// closed grid (so the seam does not show), then the seam column is duplicated
// to give it u = 1. `uv(ring, u)` gives the texture coordinates, u in [0, 1].
Mesh revolvedGrid(int rings, int slices, const std::function<glm::vec3(int, int)>& position,
                  const std::function<glm::vec2(int, float)>& uv) {
    STOA_ASSERT(rings >= 2 && slices >= 3, "revolvedGrid(): needs at least 2 rings and 3 slices");
    const auto S = static_cast<std::uint32_t>(slices);
    Mesh closed;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < slices; ++j) closed.vertices.push_back(vertex(position(i, j), {}, {}));
    auto quads = [&](Mesh& mesh, std::uint32_t rowLength, bool wrap) {
        for (std::uint32_t i = 0; i + 1 < static_cast<std::uint32_t>(rings); ++i)
            for (std::uint32_t j = 0; j < S; ++j) {
                const std::uint32_t next = wrap ? (j + 1) % S : j + 1;
                const std::uint32_t a = i * rowLength + j, b = i * rowLength + next;
                const std::uint32_t c = (i + 1) * rowLength + next, d = (i + 1) * rowLength + j;
                mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
            }
    };
    quads(closed, S, true);
    computeSmoothNormals(closed);

    Mesh open;
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j <= slices; ++j) {
            Vertex v = closed.vertices[static_cast<std::size_t>(i) * S + static_cast<std::uint32_t>(j) % S];
            v.uv = uv(i, static_cast<float>(j) / static_cast<float>(slices));
            open.vertices.push_back(v);
        }
    quads(open, S + 1, false);
    return open;
}

// A smooth profile through control points (height, radius), Catmull-Rom between them.
float profileRadius(const std::vector<glm::vec2>& points, float y) {
    if (y <= points.front().x) return points.front().y;
    if (y >= points.back().x) return points.back().y;
    std::size_t k = 0;
    while (points[k + 1].x < y) ++k;
    const float t = (y - points[k].x) / (points[k + 1].x - points[k].x);
    const float p0 = points[k > 0 ? k - 1 : k].y, p1 = points[k].y, p2 = points[k + 1].y;
    const float p3 = points[k + 2 < points.size() ? k + 2 : k + 1].y;
    const float t2 = t * t, t3 = t2 * t;
    return 0.5f * (2.0f * p1 + (p2 - p0) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                   (3.0f * p1 - p0 - 3.0f * p2 + p3) * t3);
}

glm::vec3 around(float radius, float angle, float y) { return {radius * sine(angle), y, radius * cosine(angle)}; }

} // namespace

Mesh floorMesh(float size, int cells) {
    Mesh mesh;
    const float half = 0.5f * size, step = size / static_cast<float>(cells);
    const auto row = static_cast<std::uint32_t>(cells + 1);
    for (int i = 0; i <= cells; ++i)        // rows from -Z (far) to +Z (near)
        for (int j = 0; j <= cells; ++j) {  // columns from -X to +X
            const glm::vec3 p(-half + step * static_cast<float>(j), 0.0f, -half + step * static_cast<float>(i));
            mesh.vertices.push_back(vertex(p, {0.0f, 1.0f, 0.0f}, glm::vec2(p.x, -p.z) / 2.0f));
        }
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(cells); ++i)
        for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(cells); ++j) {
            // Seen from above: (i+1, j) is the near-left corner, counter-clockwise from there.
            const std::uint32_t nearLeft = (i + 1) * row + j, nearRight = nearLeft + 1;
            const std::uint32_t farLeft = i * row + j, farRight = farLeft + 1;
            mesh.indices.insert(mesh.indices.end(), {nearLeft, nearRight, farRight, nearLeft, farRight, farLeft});
        }
    return mesh;
}

Mesh columnMesh() {
    Mesh mesh;
    constexpr float kMarbleRepeat = 2.0f;  // metres per repeat of the marble texture along the column
    addBox(mesh, {-0.55f, 0.0f, -0.55f}, {0.55f, 0.2f, 0.55f}, kMarbleRepeat);  // plinth

    // Base ring (a torus-like moulding) from y = 0.2 to 0.32.
    constexpr int kRoundSlices = 48;
    const std::vector<glm::vec2> baseProfile{{0.20f, 0.46f}, {0.23f, 0.50f}, {0.27f, 0.51f}, {0.31f, 0.47f}, {0.32f, 0.43f}};
    append(mesh, revolvedGrid(
                     9, kRoundSlices,
                     [&](int ring, int slice) {
                         const float y = 0.20f + 0.12f * static_cast<float>(ring) / 8.0f;
                         return around(profileRadius(baseProfile, y), kTwoPi * static_cast<float>(slice) / kRoundSlices, y);
                     },
                     [](int ring, float u) { return glm::vec2(u, (0.20f + 0.015f * static_cast<float>(ring)) / kMarbleRepeat); }));

    // Shaft: 20 concave flutes. The vertices are shared around the shaft, so
    // smooth normals turn each flute into a soft groove; facet normals show the strips.
    constexpr int kFlutes = 20, kSegmentsPerFlute = 4, kRings = 16;
    constexpr float kShaftBottom = 0.32f, kShaftTop = 4.60f, kFluteDepth = 0.035f;
    append(mesh, revolvedGrid(
                     kRings, kFlutes * kSegmentsPerFlute,
                     [&](int ring, int slice) {
                         const float t = static_cast<float>(ring) / (kRings - 1);
                         const float y = kShaftBottom + t * (kShaftTop - kShaftBottom);
                         // Taper from 0.43 m to 0.35 m with a slight swelling (entasis).
                         const float radius = 0.43f - 0.08f * t + 0.012f * sine(glm::pi<float>() * t);
                         const float inFlute = static_cast<float>(slice % kSegmentsPerFlute) / kSegmentsPerFlute;
                         const float groove = kFluteDepth * sine(glm::pi<float>() * inFlute);
                         return around(radius - groove, kTwoPi * static_cast<float>(slice) / (kFlutes * kSegmentsPerFlute), y);
                     },
                     [&](int ring, float u) {
                         const float y = kShaftBottom + static_cast<float>(ring) / (kRings - 1) * (kShaftTop - kShaftBottom);
                         return glm::vec2(u, y / kMarbleRepeat);
                     }));

    // Echinus: a cushion flaring from the shaft's top to the abacus.
    const std::vector<glm::vec2> echinusProfile{{4.60f, 0.35f}, {4.66f, 0.37f}, {4.74f, 0.45f}, {4.80f, 0.52f}, {4.85f, 0.54f}};
    append(mesh, revolvedGrid(
                     9, kRoundSlices,
                     [&](int ring, int slice) {
                         const float y = 4.60f + 0.25f * static_cast<float>(ring) / 8.0f;
                         return around(profileRadius(echinusProfile, y), kTwoPi * static_cast<float>(slice) / kRoundSlices, y);
                     },
                     [](int ring, float u) { return glm::vec2(u, (4.60f + 0.03125f * static_cast<float>(ring)) / kMarbleRepeat); }));
    addBox(mesh, {-0.62f, 4.85f, -0.62f}, {0.62f, 5.05f, 0.62f}, kMarbleRepeat);  // abacus
    return mesh;
}

Mesh wallMesh() {
    Mesh mesh;
    addBox(mesh, {-4.0f, 0.0f, -0.3f}, {4.0f, 3.0f, 0.3f}, 2.0f);
    return mesh;
}

Mesh templeMesh() {
    Mesh mesh;
    constexpr float kRepeat = 3.0f;  // metres per repeat of the limestone texture
    addBox(mesh, {-6.0f, 0.00f, -4.5f}, {6.0f, 0.35f, 4.5f}, kRepeat);  // steps
    addBox(mesh, {-5.6f, 0.35f, -4.1f}, {5.6f, 0.70f, 4.1f}, kRepeat);
    addBox(mesh, {-5.2f, 0.70f, -3.7f}, {5.2f, 1.05f, 3.7f}, kRepeat);  // stylobate
    addBox(mesh, {-4.0f, 1.05f, -2.8f}, {4.0f, 5.00f, 2.8f}, kRepeat);  // cella
    addBox(mesh, {-4.6f, 5.00f, -3.4f}, {4.6f, 5.80f, 3.4f}, kRepeat);  // entablature

    // Gabled roof: ridge along Z at y = 7.3, eaves at y = 5.8 overhanging to x = +-4.8.
    const float eave = 5.8f, ridge = 7.3f, x = 4.8f, z = 3.5f;
    addFlat(mesh, {{-x, eave, z}, {x, eave, z}, {0.0f, ridge, z}}, kRepeat);     // front pediment
    addFlat(mesh, {{x, eave, -z}, {-x, eave, -z}, {0.0f, ridge, -z}}, kRepeat);  // back pediment
    addFlat(mesh, {{x, eave, z}, {x, eave, -z}, {0.0f, ridge, -z}, {0.0f, ridge, z}}, kRepeat);    // +X slope
    addFlat(mesh, {{-x, eave, -z}, {-x, eave, z}, {0.0f, ridge, z}, {0.0f, ridge, -z}}, kRepeat);  // -X slope
    addFlat(mesh, {{-x, eave, -z}, {x, eave, -z}, {x, eave, z}, {-x, eave, z}}, kRepeat);          // soffit
    return mesh;
}

Mesh statueMesh(int slices, int rings) {
    STOA_ASSERT(slices >= 3 && rings >= 2, "statueMesh(): needs at least 3 slices and 2 rings");
    constexpr float kTop = 1.97f;
    // (height, radius) of the figure's outline, bottom to top: robe, hips, waist,
    // chest, shoulders, neck, jaw, head.
    const std::vector<glm::vec2> outline{{0.00f, 0.30f}, {0.08f, 0.30f}, {0.16f, 0.26f}, {0.50f, 0.22f}, {0.90f, 0.18f},
                                         {1.10f, 0.155f}, {1.30f, 0.19f}, {1.44f, 0.205f}, {1.52f, 0.12f}, {1.58f, 0.065f},
                                         {1.65f, 0.06f}, {1.70f, 0.085f}, {1.79f, 0.108f}, {1.88f, 0.095f}, {1.94f, 0.055f},
                                         {kTop, 0.0f}};
    auto gauss = [](float x, float width) { return static_cast<float>(portableExp(-(x * x) / (width * width))); };

    Mesh mesh;
    auto point = [&](int ring, int slice) {
        // Rings are spaced evenly in height, the last just below the pole.
        const float y = kTop * static_cast<float>(ring) / static_cast<float>(rings);
        const float angle = kTwoPi * static_cast<float>(slice) / static_cast<float>(slices);
        float radius = profileRadius(outline, y);
        // Drapery: vertical folds on the robe, fading out above the hips.
        const float folds = 0.5f + 0.5f * sine(13.0f * angle + 4.0f * fbm3(0.0f, y * 1.5f, angle, 2, 11U));
        radius += 0.018f * folds * (1.0f - glm::smoothstep(0.8f, 1.15f, y));
        // Arms hanging at the sides (angle +-90 degrees) from shoulder to hip.
        const float side = std::min(std::abs(angle - 0.5f * glm::pi<float>()), std::abs(angle - 1.5f * glm::pi<float>()));
        radius += 0.055f * gauss(side, 0.35f) * glm::smoothstep(0.85f, 1.0f, y) * (1.0f - glm::smoothstep(1.40f, 1.50f, y));
        // A nose and a brow on the face (angle 0, towards +Z).
        const float front = std::min(angle, kTwoPi - angle);
        radius += 0.022f * gauss(front, 0.18f) * gauss(y - 1.77f, 0.025f);
        radius += 0.008f * gauss(front, 0.6f) * gauss(y - 1.82f, 0.012f);
        // Weathering: fine noise everywhere.
        const glm::vec3 onAxis = around(1.0f, angle, y);
        radius += 0.006f * (fbm3(onAxis.x * 9.0f, onAxis.y * 9.0f, onAxis.z * 9.0f, 3, 29U) - 0.5f);
        radius = std::max(radius, 0.0f);
        // Broader across the shoulders than front to back.
        const float broad = 1.0f + 0.3f * glm::smoothstep(0.7f, 1.2f, y) * (1.0f - glm::smoothstep(1.48f, 1.56f, y));
        return glm::vec3(broad * radius * sine(angle), y, 0.85f * radius * cosine(angle));
    };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < slices; ++j) mesh.vertices.push_back(vertex(point(i, j), {}, {}));
    const auto S = static_cast<std::uint32_t>(slices), R = static_cast<std::uint32_t>(rings);
    for (std::uint32_t i = 0; i + 1 < R; ++i)
        for (std::uint32_t j = 0; j < S; ++j) {
            const std::uint32_t a = i * S + j, b = i * S + (j + 1) % S;
            const std::uint32_t c = (i + 1) * S + (j + 1) % S, d = (i + 1) * S + j;
            mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        }
    const auto pole = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back(vertex({0.0f, kTop, 0.0f}, {}, {}));
    const std::uint32_t centre = pole + 1;
    mesh.vertices.push_back(vertex({0.0f, 0.0f, 0.0f}, {}, {}));
    for (std::uint32_t j = 0; j < S; ++j) {
        const std::uint32_t next = (j + 1) % S;
        mesh.indices.insert(mesh.indices.end(), {(R - 1) * S + j, (R - 1) * S + next, pole});
        mesh.indices.insert(mesh.indices.end(), {j, centre, next});
    }
    return mesh;
}

} // namespace stoa::assets
