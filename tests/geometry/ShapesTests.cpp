#include "catch.hpp"
#include "MeshChecks.hpp"

#include <stoa/geometry/Shapes.hpp>

#include <glm/gtc/constants.hpp>

using namespace stoa;
using stoa::test::near;

namespace {

/// What every shape promises: a valid mesh, unit normals, uvs in [0, 1],
/// triangles counter-clockwise seen from where their normals point.
void checkCommonPromises(const Mesh& mesh) {
    CHECK_NOTHROW(mesh.validate("shape"));
    const std::string nonUnit = test::firstNonUnitNormal(mesh);
    INFO(nonUnit);
    CHECK(nonUnit.empty());
    const std::string uvOutside = test::firstUvOutsideUnitSquare(mesh);
    INFO(uvOutside);
    CHECK(uvOutside.empty());
    const std::string againstNormals = test::firstTriangleAgainstNormals(mesh);
    INFO(againstNormals);
    CHECK(againstNormals.empty());
}

void checkBounds(const Mesh& mesh, glm::vec3 lower, glm::vec3 upper) {
    const auto [actualLower, actualUpper] = mesh.bounds();
    INFO("bounds " << glm::to_string(actualLower) << " .. " << glm::to_string(actualUpper));
    CHECK(near(actualLower, lower));
    CHECK(near(actualUpper, upper));
}

} // namespace

TEST_CASE("shapes::plane is a subdivided square in XZ facing +Y", "[geometry][shapes]") {
    const Mesh mesh = shapes::plane(2.0f, 3);
    CHECK(mesh.vertices.size() == 16);
    CHECK(mesh.triangleCount() == 18);
    checkCommonPromises(mesh);
    checkBounds(mesh, {-1, 0, -1}, {1, 0, 1});
    for (const Vertex& v : mesh.vertices) CHECK(near(v.normal, {0, 1, 0}));
    CHECK(near(test::surfaceArea(mesh), 4.0f, 1e-4f));

    // Seen from above with -Z at the top, the texture is upright: u along +X, v along -Z.
    for (const Vertex& v : mesh.vertices) {
        CHECK(near(v.uv, {(v.position.x + 1.0f) / 2.0f, (1.0f - v.position.z) / 2.0f}));
    }
}

TEST_CASE("shapes::plane defaults to one unit quad", "[geometry][shapes]") {
    const Mesh mesh = shapes::plane();
    CHECK(mesh.vertices.size() == 4);
    CHECK(mesh.triangleCount() == 2);
    checkBounds(mesh, {-0.5f, 0, -0.5f}, {0.5f, 0, 0.5f});
}

TEST_CASE("shapes::cube has 24 vertices with flat outward normals", "[geometry][shapes]") {
    const Mesh mesh = shapes::cube(2.0f);
    CHECK(mesh.vertices.size() == 24);
    CHECK(mesh.triangleCount() == 12);
    checkCommonPromises(mesh);
    checkBounds(mesh, {-1, -1, -1}, {1, 1, 1});
    const std::string inward = test::firstInwardNormal(mesh, [](glm::vec3 p) { return p; });
    INFO(inward);
    CHECK(inward.empty());
    CHECK(near(test::signedVolume(mesh), 8.0f, 1e-4f));

    for (const Vertex& v : mesh.vertices) {
        // Each normal is a coordinate axis, and the vertex lies on that face.
        CHECK(near(glm::abs(v.normal.x) + glm::abs(v.normal.y) + glm::abs(v.normal.z), 1.0f));
        CHECK(near(glm::dot(v.position, v.normal), 1.0f));
        // Each face has the whole uv square at its corners.
        CHECK((v.uv.x == 0.0f || v.uv.x == 1.0f));
        CHECK((v.uv.y == 0.0f || v.uv.y == 1.0f));
    }
    // The front face (+Z) reads upright: u along +X, v along +Y.
    for (const Vertex& v : mesh.vertices) {
        if (!near(v.normal, {0, 0, 1})) continue;
        CHECK(near(v.uv, {(v.position.x + 1.0f) / 2.0f, (v.position.y + 1.0f) / 2.0f}));
    }
}

TEST_CASE("shapes::sphere is a UV sphere with radial normals", "[geometry][shapes]") {
    const float radius = 0.5f;
    const Mesh mesh = shapes::sphere(radius, 32, 16);
    CHECK(mesh.vertices.size() == 33 * 17);
    CHECK(mesh.triangleCount() == 2 * 32 * 15);
    checkCommonPromises(mesh);
    checkBounds(mesh, glm::vec3(-radius), glm::vec3(radius));
    const std::string inward = test::firstInwardNormal(mesh, [](glm::vec3 p) { return p; });
    INFO(inward);
    CHECK(inward.empty());
    for (const Vertex& v : mesh.vertices) {
        CHECK(near(glm::length(v.position), radius));
        CHECK(near(v.normal, v.position / radius));
    }
    // A polyhedron inscribed in the sphere: a little less than 4/3 pi r^3.
    const float volume = test::signedVolume(mesh);
    const float ballVolume = 4.0f / 3.0f * glm::pi<float>() * radius * radius * radius;
    CHECK(volume > 0.97f * ballVolume);
    CHECK(volume < ballVolume);

    // v runs from the south pole (0) to the north pole (1).
    for (const Vertex& v : mesh.vertices) {
        if (near(v.position.y, radius)) CHECK(v.uv.y == 1.0f);
        if (near(v.position.y, -radius)) CHECK(v.uv.y == 0.0f);
    }
}

TEST_CASE("shapes::sphere works with the fewest segments allowed", "[geometry][shapes]") {
    const Mesh mesh = shapes::sphere(1.0f, 3, 2);
    CHECK(mesh.vertices.size() == 4 * 3);
    CHECK(mesh.triangleCount() == 2 * 3 * 1);
    checkCommonPromises(mesh);
    CHECK(test::signedVolume(mesh) > 0.0f);
}

TEST_CASE("shapes::cylinder is closed, with radial sides and flat caps", "[geometry][shapes]") {
    const float radius = 0.5f, height = 2.0f;
    const Mesh mesh = shapes::cylinder(radius, height, 32);
    CHECK(mesh.vertices.size() == 4 * 32 + 4);
    CHECK(mesh.triangleCount() == 4 * 32);
    checkCommonPromises(mesh);
    checkBounds(mesh, {-radius, -1, -radius}, {radius, 1, radius});
    const std::string inward = test::firstInwardNormal(mesh, [](glm::vec3 p) { return p; });
    INFO(inward);
    CHECK(inward.empty());

    int capVertices = 0;
    for (const Vertex& v : mesh.vertices) {
        if (near(glm::abs(v.normal.y), 1.0f)) {
            ++capVertices;
            CHECK(near(v.position.y, v.normal.y * height / 2.0f));  // on the cap the normal points away from
        } else {
            CHECK(near(v.normal.y, 0.0f));
            CHECK(near(v.normal * radius, {v.position.x, 0.0f, v.position.z}));
        }
    }
    CHECK(capVertices == 2 * 33);
    const float volume = test::signedVolume(mesh);
    const float exactVolume = glm::pi<float>() * radius * radius * height;
    CHECK(volume > 0.99f * exactVolume);
    CHECK(volume < exactVolume);
}

TEST_CASE("shapes::torus lies in the XZ plane with normals away from the tube's centre", "[geometry][shapes]") {
    const float major = 0.4f, minor = 0.15f;
    const Mesh mesh = shapes::torus(major, minor, 48, 24);
    CHECK(mesh.vertices.size() == 49 * 25);
    CHECK(mesh.triangleCount() == 2 * 48 * 24);
    checkCommonPromises(mesh);
    checkBounds(mesh, {-(major + minor), -minor, -(major + minor)}, {major + minor, minor, major + minor});

    auto fromTubeCentre = [major](glm::vec3 p) {
        const glm::vec3 radial = glm::normalize(glm::vec3(p.x, 0.0f, p.z));
        return p - major * radial;
    };
    const std::string inward = test::firstInwardNormal(mesh, fromTubeCentre);
    INFO(inward);
    CHECK(inward.empty());
    for (const Vertex& v : mesh.vertices) CHECK(near(fromTubeCentre(v.position), minor * v.normal));

    const float volume = test::signedVolume(mesh);
    const float exactVolume = 2.0f * glm::pi<float>() * glm::pi<float>() * major * minor * minor;
    CHECK(volume > 0.98f * exactVolume);
    CHECK(volume < exactVolume);
}

TEST_CASE("shapes close their uv seams exactly", "[geometry][shapes]") {
    // Every vertex at u = 1 that a triangle uses has a twin at u = 0 in the
    // very same place, so no crack can open along the seam.
    auto openSeams = [](const Mesh& mesh) {
        std::vector<bool> used(mesh.vertices.size(), mesh.indices.empty());
        for (std::uint32_t index : mesh.indices) used[index] = true;
        int open = 0;
        for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
            const Vertex& end = mesh.vertices[i];
            if (end.uv.x != 1.0f || !used[i]) continue;
            bool twin = false;
            for (const Vertex& start : mesh.vertices) {
                twin = twin || (start.uv.x == 0.0f && start.uv.y == end.uv.y && start.position == end.position);
            }
            open += twin ? 0 : 1;
        }
        return open;
    };
    CHECK(openSeams(shapes::sphere(0.5f, 7, 5)) == 0);
    CHECK(openSeams(shapes::torus(0.4f, 0.15f, 9, 7)) == 0);
    const Mesh cylinder = shapes::cylinder(0.5f, 1.0f, 7);
    Mesh side;  // the caps have no seam; their uvs are a disc
    for (const Vertex& v : cylinder.vertices) {
        if (v.normal.y == 0.0f) side.vertices.push_back(v);
    }
    CHECK(side.vertices.size() == 16);
    CHECK(openSeams(side) == 0);
}
