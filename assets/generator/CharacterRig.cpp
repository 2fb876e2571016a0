#include "CharacterRig.hpp"

#include "PortableMath.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <utility>

namespace stoa::assets::rig {

float sine(double angle) { return static_cast<float>(portableSin(angle)); }

float cosine(double angle) { return static_cast<float>(portableCos(angle)); }

float radians(double degrees) { return static_cast<float>(degrees * kPi / 180.0); }

// Rotations by `angle` radians, counter-clockwise looking down the axis at the origin.
Transform rotateX(float angle) {
    Transform t;
    const float c = cosine(angle), s = sine(angle);
    t.rotation[1] = {0.0f, c, s};
    t.rotation[2] = {0.0f, -s, c};
    return t;
}

Transform rotateY(float angle) {
    Transform t;
    const float c = cosine(angle), s = sine(angle);
    t.rotation[0] = {c, 0.0f, -s};
    t.rotation[2] = {s, 0.0f, c};
    return t;
}

Transform rotateZ(float angle) {
    Transform t;
    const float c = cosine(angle), s = sine(angle);
    t.rotation[0] = {c, s, 0.0f};
    t.rotation[1] = {-s, c, 0.0f};
    return t;
}

Transform translate(const glm::vec3& offset) {
    Transform t;
    t.translation = offset;
    return t;
}

/// A limb hanging along -Y swung forward (towards +Z) by `angle`.
Transform swing(float angle) { return rotateX(-angle); }

Piece moved(Piece piece, const Transform& transform) {
    for (glm::vec3& p : piece.positions) p = transform.point(p);
    for (glm::vec3& n : piece.normals) n = transform.direction(n);
    return piece;
}

/// A box of `size` around `center`, a flat normal per face; each face spans the whole island.
Piece box(const glm::vec3& center, const glm::vec3& size, Paint paint) {
    Piece piece;
    piece.paint = paint;
    const glm::vec3 half = size * 0.5f;
    // Each face: its normal and two axes along it with u x v = normal.
    const glm::vec3 faces[6][3] = {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                   {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                   {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}};
    for (const auto& [n, u, v] : faces) {
        int corner[4];
        for (int i = 0; i < 4; ++i) {
            const float su = (i == 1 || i == 2) ? 1.0f : -1.0f, sv = i >= 2 ? 1.0f : -1.0f;
            corner[i] = piece.vertex(center + half * (n + su * u + sv * v), n, {0.5f + 0.5f * su, 0.5f + 0.5f * sv});
        }
        piece.triangle(corner[0], corner[1], corner[2]);
        piece.triangle(corner[0], corner[2], corner[3]);
    }
    return piece;
}

/// An ellipsoid of `radii` around `center`: `slices` around Y, `stacks` from top to bottom.
Piece ellipsoid(const glm::vec3& center, const glm::vec3& radii, int slices, int stacks, Paint paint) {
    Piece piece;
    piece.paint = paint;
    for (int i = 0; i <= stacks; ++i) {
        const double polar = kPi * i / stacks;
        for (int j = 0; j <= slices; ++j) {
            const double around = 2.0 * kPi * j / slices;
            const glm::vec3 unit(sine(polar) * cosine(around), cosine(polar), sine(polar) * sine(around));
            piece.vertex(center + radii * unit, glm::normalize(unit / radii),
                         {static_cast<float>(j) / slices, 1.0f - static_cast<float>(i) / stacks});
        }
    }
    const int row = slices + 1;
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const int a = i * row + j, b = a + 1, c = a + row + 1, d = a + row;
            if (i > 0) piece.triangle(a, b, c);            // the top row's first triangle would be a point
            if (i < stacks - 1) piece.triangle(a, c, d);   // the bottom row's second one too
        }
    }
    return piece;
}

/// A capped cylinder hanging from the origin along -Y, `length` long, radius
/// `top` at y = 0 and `bottom` at y = -length, `slices` around.
Piece cylinder(float length, float top, float bottom, int slices, Paint paint) {
    Piece piece;
    piece.paint = paint;
    const float slope = (top - bottom) / length;   // the side's normal leans down where it narrows downwards
    for (int j = 0; j <= slices; ++j) {
        const double around = 2.0 * kPi * j / slices;
        const float c = cosine(around), s = sine(around);
        const glm::vec3 normal = glm::normalize(glm::vec3(c, -slope, s));
        const float u = static_cast<float>(j) / slices;
        piece.vertex({top * c, 0.0f, top * s}, normal, {u, 1.0f});
        piece.vertex({bottom * c, -length, bottom * s}, normal, {u, 0.0f});
    }
    for (int j = 0; j < slices; ++j) {
        piece.triangle(2 * j, 2 * j + 2, 2 * j + 3);
        piece.triangle(2 * j, 2 * j + 3, 2 * j + 1);
    }
    for (const auto& [y, radius, ny] : {std::tuple{0.0f, top, 1.0f}, std::tuple{-length, bottom, -1.0f}}) {
        const int first = static_cast<int>(piece.positions.size());
        for (int j = 0; j < slices; ++j) {
            const double around = 2.0 * kPi * j / slices;
            const float c = cosine(around), s = sine(around);
            piece.vertex({radius * c, y, radius * s}, {0.0f, ny, 0.0f}, {0.5f + 0.5f * c, 0.5f + 0.5f * s});
        }
        for (int j = 1; j + 1 < slices; ++j) piece.triangle(first, first + j, first + j + 1);
    }
    return piece;
}

/// The same cylinder starting at `from` and pointing along `rotation` applied to -Y.
Piece limb(const glm::vec3& from, const Transform& rotation, float length, float top, float bottom, int slices, Paint paint) {
    return moved(cylinder(length, top, bottom, slices, paint), translate(from) * rotation);
}

/// A 0..1 phase of a cycle of `frames` frames as an angle: frame `frames` would be frame 0 again.
double cycle(int frame, int frames) { return 2.0 * kPi * frame / frames; }

} // namespace stoa::assets::rig
