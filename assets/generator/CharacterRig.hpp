#pragma once
// The rig the characters are built from (Characters.cpp): rigid motions,
// pieces of geometry painted by island, parts in a tree, animations as poses.

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace stoa::assets::rig {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSkinSize = 128;
constexpr int kCell = 32;   // the skin is 4 x 4 islands of 32 x 32 pixels, one per paint

float sine(double angle);      // the portable ones (PortableMath.hpp), as floats
float cosine(double angle);
float radians(double degrees);

/// What a piece is painted with: the index of its island in the skin.
enum class Paint { Body, Dark, Leg, Eye, Belly, Nose, Accent, Tire, Crate, Count };

/// A rigid motion: p -> rotation * p + translation.
struct Transform {
    glm::mat3 rotation{1.0f};
    glm::vec3 translation{0.0f};

    glm::vec3 point(const glm::vec3& p) const { return rotation * p + translation; }
    glm::vec3 direction(const glm::vec3& d) const { return rotation * d; }
    Transform operator*(const Transform& inner) const { return {rotation * inner.rotation, point(inner.translation)}; }
};

// Rotations by `angle` radians, counter-clockwise looking down the axis at the origin.
Transform rotateX(float angle);
Transform rotateY(float angle);
Transform rotateZ(float angle);
Transform translate(const glm::vec3& offset);

/// A limb hanging along -Y swung forward (towards +Z) by `angle`.
Transform swing(float angle);

/// Triangles with uvs in [0, 1] over the piece's island.
struct Piece {
    Paint paint = Paint::Body;
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::array<int, 3>> triangles;

    int vertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv) {
        positions.push_back(position);
        normals.push_back(normal);
        uvs.push_back(uv);
        return static_cast<int>(positions.size()) - 1;
    }
    /// Adds a triangle counter-clockwise seen from outside: the side its vertex normals point to.
    void triangle(int a, int b, int c) {
        const glm::vec3 face = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        if (glm::dot(face, normals[a] + normals[b] + normals[c]) < 0.0f) std::swap(b, c);
        triangles.push_back({a, b, c});
    }
};

Piece moved(Piece piece, const Transform& transform);

/// A box of `size` around `center`, a flat normal per face; each face spans the whole island.
Piece box(const glm::vec3& center, const glm::vec3& size, Paint paint);

/// An ellipsoid of `radii` around `center`: `slices` around Y, `stacks` from top to bottom.
Piece ellipsoid(const glm::vec3& center, const glm::vec3& radii, int slices, int stacks, Paint paint);

/// A capped cylinder hanging from the origin along -Y, `length` long, radius
/// `top` at y = 0 and `bottom` at y = -length, `slices` around.
Piece cylinder(float length, float top, float bottom, int slices, Paint paint);

/// The same cylinder starting at `from` and pointing along `rotation` applied to -Y.
Piece limb(const glm::vec3& from, const Transform& rotation, float length, float top, float bottom, int slices, Paint paint);

struct Part {
    int parent = -1;        // parts come after their parents
    glm::vec3 joint{0.0f};  // in the parent's space (the model's for a root)
    std::vector<Piece> pieces;
};

/// One pose per frame: each part's motion about its joint, in its parent's space.
using Pose = std::vector<Transform>;

struct Animation {
    std::string name;
    int frames = 0;
    /// How the frame sits on the ground: kept standing on y = 0, or only lifted out of it (a leap).
    bool grounded = true;
    std::function<void(int frame, Pose& pose)> pose;
};

struct Rig {
    std::vector<Part> parts;
    float scale = 1.0f;   // of the whole model, after posing

    int add(int parent, const glm::vec3& joint, std::vector<Piece> pieces) {
        parts.push_back({parent, joint, std::move(pieces)});
        return static_cast<int>(parts.size()) - 1;
    }
};

/// A 0..1 phase of a cycle of `frames` frames as an angle: frame `frames` would be frame 0 again.
double cycle(int frame, int frames);

} // namespace stoa::assets::rig
