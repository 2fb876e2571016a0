// Lab 04's property checks; see checks.hpp. They call your normalMapFromHeight()
// on height maps of their own and test a property the docs state, not values.

#include "checks.hpp"
#include "lab04.hpp"

#include <stoa/geometry/Mesh.hpp>
#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace lab04 {

namespace {

// A small height map of random heights (a fixed seed: the same map every run).
stoa::Image randomHeights(int width, int height) {
    stoa::Image image(width, height, 1);
    stoa::CheckRandom random(20261123u);
    for (int i = 0; i < width * height; ++i) image.data()[i] = random.nextByte();
    return image;
}

// `image` moved right by dx and down by dy as a tile: what leaves one border comes in at the other.
stoa::Image shiftedAround(const stoa::Image& image, int dx, int dy) {
    stoa::Image shifted(image.width(), image.height(), image.channels());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            shifted.setPixel((x + dx) % image.width(), (y + dy) % image.height(), image.pixel(x, y));
    return shifted;
}

} // namespace

stoa::CheckResult checkNormalMapWraps() {
    const int width = 24, height = 16, dx = 7, dy = 5;
    const float strength = 4.0f;
    const stoa::Image heights = randomHeights(width, height);
    const stoa::Image expected = shiftedAround(stoa::normalMapFromHeight(heights, strength), dx, dy);
    const stoa::Image normals = stoa::normalMapFromHeight(shiftedAround(heights, dx, dy), strength);
    if (normals.width() != width || normals.height() != height || normals.channels() < 3)
        return stoa::CheckResult::fail("normalMapFromHeight() returned a " + std::to_string(normals.width()) + "x" +
                                       std::to_string(normals.height()) + " image with " +
                                       std::to_string(normals.channels()) + " channels for a " +
                                       std::to_string(width) + "x" + std::to_string(height) +
                                       " height map (expected the same size, RGB; docs: From heights to normals)");

    // Texels whose normal is not the shifted one; they are told apart by where they lie.
    int differing = 0, onBorder = 0, firstX = -1, firstY = -1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::u8vec4 a = normals.pixel(x, y), b = expected.pixel(x, y);
            bool same = true;
            for (int c = 0; c < 3; ++c) same = same && std::abs(int(a[c]) - int(b[c])) <= 1;
            if (same) continue;
            if (differing++ == 0) firstX = x, firstY = y;
            // On a border of the shifted map, or where a border of the original one landed.
            const int sourceX = (x - dx + width) % width, sourceY = (y - dy + height) % height;
            if (x == 0 || y == 0 || x == width - 1 || y == height - 1 || sourceX == 0 || sourceY == 0 ||
                sourceX == width - 1 || sourceY == height - 1)
                ++onBorder;
        }
    const std::string shift = "shifting a " + std::to_string(width) + "x" + std::to_string(height) +
                              " height map around by (" + std::to_string(dx) + ", " + std::to_string(dy) + ") texels";
    if (differing == 0) return stoa::CheckResult::pass(shift + " shifts its normal map by the same texels");
    std::string where = " (first at texel (" + std::to_string(firstX) + ", " + std::to_string(firstY) + ") of the shifted map)";
    if (onBorder == differing)
        return stoa::CheckResult::fail(shift + " changed " + std::to_string(differing) +
                                       " normals next to the borders of the map" + where +
                                       ": the maps tile, so the neighbour left of column 0 is the last column and the "
                                       "row above row 0 is the last row (docs: From heights to normals)");
    return stoa::CheckResult::fail(shift + " changed " + std::to_string(differing) + " normals, " +
                                   std::to_string(differing - onBorder) + " of them away from the borders" + where +
                                   ": a texel's normal must depend only on the heights around it "
                                   "(docs: From heights to normals)");
}

stoa::CheckResult checkNormalMapEncoding() {
    // Flat height maps at three heights: every normal is the unbent (0, 0, 1).
    for (const int level : {0, 77, 255}) {
        stoa::Image heights(6, 4, 1);
        for (int i = 0; i < heights.width() * heights.height(); ++i)
            heights.data()[i] = static_cast<std::uint8_t>(level);
        const stoa::Image normals = stoa::normalMapFromHeight(heights, 4.0f);
        if (normals.width() != heights.width() || normals.height() != heights.height() || normals.channels() < 3)
            return stoa::CheckResult::fail("normalMapFromHeight() returned a " + std::to_string(normals.width()) +
                                           "x" + std::to_string(normals.height()) + " image with " +
                                           std::to_string(normals.channels()) +
                                           " channels for a 6x4 height map (expected the same size, RGB; docs: From "
                                           "heights to normals)");
        for (int y = 0; y < normals.height(); ++y)
            for (int x = 0; x < normals.width(); ++x) {
                const glm::u8vec4 texel = normals.pixel(x, y);
                if (texel.r == 128 && texel.g == 128 && texel.b == 255) continue;
                return stoa::CheckResult::fail(
                    "normalMapFromHeight() of a flat 6x4 height map (every height " + std::to_string(level) +
                    ") gives the texel (" + std::to_string(texel.r) + ", " + std::to_string(texel.g) + ", " +
                    std::to_string(texel.b) + ") at (" + std::to_string(x) + ", " + std::to_string(y) +
                    "); the unbent normal (0, 0, 1) is stored as round((n * 0.5 + 0.5) * 255) = (128, 128, 255): "
                    "rounded, not cut off (docs: From heights to normals)");
            }
    }
    return stoa::CheckResult::pass("flat height maps give (128, 128, 255) everywhere: round((n * 0.5 + 0.5) * 255) "
                                   "of the unbent normal");
}

namespace {

std::string tangentText(const glm::vec4& t) {
    char text[112];
    std::snprintf(text, sizeof text, "(%.3f, %.3f, %.3f, w %.1f)", t.x, t.y, t.z, t.w);
    return text;
}

bool finite(const glm::vec4& t) {
    return std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w);
}

/// A mesh with the given vertex normals, with computeTangents() run on it.
stoa::Mesh meshWithTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                            const std::vector<glm::vec2>& uvs, std::vector<std::uint32_t> indices) {
    stoa::Mesh mesh;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        stoa::Vertex vertex{};
        vertex.position = positions[i];
        vertex.normal = normals[i];
        vertex.uv = uvs[i];
        mesh.vertices.push_back(vertex);
    }
    mesh.indices = std::move(indices);
    stoa::computeTangents(mesh);
    return mesh;
}

/// A mesh in the z = 0 plane, every normal +Z, with computeTangents() run on it.
stoa::Mesh flatMeshWithTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec2>& uvs,
                                std::vector<std::uint32_t> indices) {
    return meshWithTangents(positions, std::vector<glm::vec3>(positions.size(), glm::vec3(0.0f, 0.0f, 1.0f)), uvs,
                            std::move(indices));
}

} // namespace

stoa::CheckResult checkTangentsWithoutNans() {
    // Vertices 0-2: a good triangle in the XY plane, u along +X, v along +Y.
    // Vertices 0, 3, 4: a triangle whose uvs (0,0), (1,1), (2,2) lie on a line.
    // Vertices 5-7: a triangle with the same uv on all three corners.
    const stoa::Mesh mesh = flatMeshWithTangents(
        {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {3, 0, 0}, {4, 0, 0}, {3, 1, 0}},
        {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 2}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}}, {0, 1, 2, 0, 3, 4, 5, 6, 7});

    const char* const what[] = {"vertex 0 (the good triangle, and one whose uvs lie on a line)",
                                "vertex 1 (the good triangle)", "vertex 2 (the good triangle)",
                                "vertex 3 (only a triangle whose uvs lie on a line)",
                                "vertex 4 (only a triangle whose uvs lie on a line)",
                                "vertex 5 (only a triangle with one uv on all corners)",
                                "vertex 6 (only a triangle with one uv on all corners)",
                                "vertex 7 (only a triangle with one uv on all corners)"};
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 t = mesh.vertices[static_cast<std::size_t>(i)].tangent;
        const std::string found = std::string("computeTangents(): the tangent of ") + what[i] + " is " + tangentText(t);
        if (!finite(t))
            return stoa::CheckResult::fail(found + ": not finite. A triangle whose uvs lie on a line (det = 0) adds "
                                                   "nothing, and a vertex whose sum is zero still gets a unit tangent "
                                                   "perpendicular to N (docs: The tangent frame)");
        const glm::vec3 xyz(t);
        if (i < 3) {
            if (glm::length(xyz - glm::vec3(1.0f, 0.0f, 0.0f)) > 1e-3f || t.w != 1.0f)
                return stoa::CheckResult::fail(found + ", expected (1, 0, 0, w 1): u grows along +X there, and a "
                                                       "triangle whose uvs lie on a line adds nothing to the sum "
                                                       "(docs: The tangent frame)");
            continue;
        }
        if (std::abs(glm::length(xyz) - 1.0f) > 1e-3f || std::abs(xyz.z) > 1e-3f || t.w != 1.0f)
            return stoa::CheckResult::fail(found + ", expected a unit tangent perpendicular to the normal (0, 0, 1), "
                                                   "with w = +1: any will do where no triangle says which way u grows "
                                                   "(docs: The tangent frame)");
    }
    // The fallback for any normal: one triangle with one uv on all corners, whose
    // corners' normals lie along the axes (a perpendicular made by crossing with
    // one fixed axis vanishes for the normal along that axis).
    const glm::vec3 axisNormals[] = {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    const stoa::Mesh axes = meshWithTangents({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                             {axisNormals[0], axisNormals[1], axisNormals[2]},
                                             {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}}, {0, 1, 2});
    for (int i = 0; i < 3; ++i) {
        const glm::vec4 t = axes.vertices[static_cast<std::size_t>(i)].tangent;
        const glm::vec3 n = axisNormals[i];
        if (!finite(t) || std::abs(glm::length(glm::vec3(t)) - 1.0f) > 1e-3f ||
            std::abs(glm::dot(glm::vec3(t), n)) > 1e-3f || t.w != 1.0f)
            return stoa::CheckResult::fail(
                "computeTangents(): a vertex with the normal " + stoa::checkVector(n) + " whose only triangle has one uv on all corners gets the tangent " + tangentText(t) +
                ", expected a finite unit tangent perpendicular to that normal, with w = +1: the fallback must "
                "work for every normal, also one along the axis it crosses with (docs: The tangent frame)");
    }
    return stoa::CheckResult::pass("triangles whose uvs lie on a line add nothing, and every vertex gets a finite "
                                   "unit tangent perpendicular to its normal, whichever way it points");
}

stoa::CheckResult checkTangentsFollowTheUvs() {
    // One triangle in the XY plane (normal +Z) whose uvs are a linear map A of
    // its (x, y): uv = A (x, y). Then the surface's (x, y) = A^-1 uv, and u grows
    // along A^-1's first column, v along its second. Maps that scale, shear,
    // mirror and turn, none of them by whole units only.
    const glm::mat2 maps[] = {
        glm::mat2(0.25f, 0.0f, 0.0f, 3.0f),     // columns: u = 0.25 x, v = 3 y
        glm::mat2(-0.4f, 0.3f, 0.7f, 1.6f),     // mirrored and sheared
        glm::mat2(0.6f, -2.0f, 1.5f, 0.5f),     // turned and stretched
        glm::mat2(2.5f, 0.2f, -0.3f, -0.8f),    // mirrored the other way
        glm::mat2(2.0f, -0.1f, 0.8f, -2.1f),    // mirrored in v, u stretched
        glm::mat2(-1.6f, 0.3f, -0.8f, 0.6f),    // mirrored in u, sheared
    };
    const glm::vec3 corners[] = {{0.2f, 0.1f, 0.0f}, {1.3f, 0.4f, 0.0f}, {0.5f, 1.7f, 0.0f}};
    for (const glm::mat2& map : maps) {
        std::vector<glm::vec2> uvs;
        for (const glm::vec3& corner : corners) uvs.push_back(map * glm::vec2(corner));
        const stoa::Mesh mesh = flatMeshWithTangents({corners[0], corners[1], corners[2]}, uvs, {0, 1, 2});
        const glm::mat2 back = glm::inverse(map);
        const glm::vec3 alongU(glm::normalize(back[0]), 0.0f), alongV(back[1], 0.0f);
        const float handedness = glm::dot(glm::cross(glm::vec3(0.0f, 0.0f, 1.0f), alongU), alongV) < 0.0f ? -1.0f : 1.0f;
        const glm::vec4 t = mesh.vertices[0].tangent;
        const std::string what = "computeTangents() of a triangle whose uvs are (" + std::to_string(map[0][0]) + " x + " +
                                 std::to_string(map[1][0]) + " y, " + std::to_string(map[0][1]) + " x + " +
                                 std::to_string(map[1][1]) + " y) gives " + tangentText(t);
        if (!finite(t) || glm::length(glm::vec3(t) - alongU) > 1e-3f)
            return stoa::CheckResult::fail(what + "; u grows along " + tangentText(glm::vec4(alongU, handedness)) +
                                           " there (solve the 2 x 2 uv system for T) (docs: The tangent frame)");
        if (t.w != handedness)
            return stoa::CheckResult::fail(what + ", w " + std::to_string(t.w) + "; v grows along " +
                                           tangentText(glm::vec4(glm::normalize(alongV), 0.0f)) +
                                           ", so w is " + std::to_string(handedness) +
                                           " (the sign of dot(cross(N, T), B), B from the same system) "
                                           "(docs: Handedness)");
    }
    // Two triangles sharing an edge, whose uvs are stretched differently: the shared
    // vertices' tangent is the sum of the two triangles' T = dp/du, as solved (each
    // triangle's own scale), then made unit: not a sum of unit vectors, nor of T
    // scaled some other way.
    {
        const stoa::Mesh mesh = flatMeshWithTangents({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0.5f, 0}},
                                                     {{0, 0}, {0.5f, 0.25f}, {-0.25f, 0.5f}, {-1.5f, 0.4f}},
                                                     {0, 1, 2, 0, 2, 3});
        // dp/du of a triangle: the first column of the inverse of its uv edges' 2 x 2 map.
        const auto alongU = [&](int a, int b, int c) {
            const std::vector<stoa::Vertex>& v = mesh.vertices;
            const glm::mat2 edges(glm::vec2(v[b].position - v[a].position), glm::vec2(v[c].position - v[a].position));
            const glm::mat2 uvEdges(v[b].uv - v[a].uv, v[c].uv - v[a].uv);
            return glm::vec3((edges * glm::inverse(uvEdges))[0], 0.0f);
        };
        const glm::vec3 expected = glm::normalize(alongU(0, 1, 2) + alongU(0, 2, 3));
        const glm::vec4 t = mesh.vertices[0].tangent;
        if (!finite(t) || glm::length(glm::vec3(t) - expected) > 1e-3f)
            return stoa::CheckResult::fail("computeTangents() gives the vertex two triangles share, whose uvs are "
                                           "stretched differently, the tangent " + tangentText(t) + "; the sum of "
                                           "the two triangles' T (each as its 2 x 2 system gives it) points along " +
                                           tangentText(glm::vec4(expected, 1.0f)) + " (docs: The tangent frame)");
    }
    // Smooth normals lean: the triangle lies in z = 0 with u along +X, but its
    // corners' normals tilt. T must lose its part along each corner's normal.
    {
        const glm::vec3 normals[] = {glm::normalize(glm::vec3(0.5f, 0.3f, 0.8f)),
                                     glm::normalize(glm::vec3(-0.4f, 0.1f, 0.9f)),
                                     glm::normalize(glm::vec3(0.2f, -0.6f, 0.7f))};
        const stoa::Mesh mesh = meshWithTangents({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                                 {normals[0], normals[1], normals[2]}, {{0, 0}, {1, 0}, {0, 1}},
                                                 {0, 1, 2});
        for (int i = 0; i < 3; ++i) {
            const glm::vec3& n = normals[i];
            const glm::vec3 expected = glm::normalize(glm::vec3(1, 0, 0) - n * n.x);
            const glm::vec4 t = mesh.vertices[static_cast<std::size_t>(i)].tangent;
            if (!finite(t) || glm::length(glm::vec3(t) - expected) > 1e-3f)
                return stoa::CheckResult::fail(
                    "computeTangents() gives a vertex whose normal " + stoa::checkVector(n) + " leans out of its triangle "
                    "(u along +X) the tangent " + tangentText(t) + "; without its part along N, made unit, T is " +
                    stoa::checkVector(expected) + " (Gram-Schmidt, step 1 per vertex) (docs: The tangent frame)");
        }
    }
    // A vertex shared by a triangle whose v grows along +Y and one whose v grows
    // along -Y, stretched `stretch` times: B_sum is the two triangles' B as solved,
    // (0, 1 - 1/stretch, 0), and w is +1 where it is zero (">= 0", docs: Handedness).
    for (const float stretch : {1.0f, 2.0f, 0.5f}) {
        const stoa::Mesh mesh = flatMeshWithTangents({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}},
                                                     {{0, 0}, {1, 0}, {0, 1}, {0, -stretch}}, {0, 1, 2, 0, 1, 3});
        const float bSum = 1.0f - 1.0f / stretch;
        const float expected = bSum >= 0.0f ? 1.0f : -1.0f;
        const glm::vec4 t = mesh.vertices[0].tangent;
        if (!finite(t) || t.w != expected)
            return stoa::CheckResult::fail(
                "computeTangents(): a vertex shared by a triangle whose v grows along +Y (B = (0, 1, 0)) and one "
                "whose v grows along -Y, its uvs stretched " + std::to_string(stretch) + " times (B = (0, " +
                std::to_string(-1.0f / stretch) + ", 0)), gets w " + std::to_string(t.w) + "; B_sum is (0, " +
                std::to_string(bSum) + ", 0), so w is " + std::to_string(expected) +
                " (+1 when dot(cross(N, T), B_sum) >= 0; B as each triangle's 2 x 2 system gives it) "
                "(docs: Handedness)");
    }
    return stoa::CheckResult::pass("tangents and handedness follow u and v for six uv maps that scale, shear, "
                                   "mirror and turn, a shared vertex sums its triangles' T and B as solved, and T "
                                   "loses its part along a leaning normal");
}

} // namespace lab04
