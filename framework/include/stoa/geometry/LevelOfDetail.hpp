#pragma once
// Levels of detail of a mesh: simplified copies with fewer triangles, made by
// meshoptimizer's simplifier (edge collapses ordered by a quadric error, after
// Garland and Heckbert 1997). Lab 06 draws a far object with a coarse level;
// choosing the level is the student's part, making them is the framework's.
//
//   std::vector<LodLevel> levels = buildLevelsOfDetail(statue, {1.0f, 0.5f, 0.25f, 0.1f});
//   levels[2].mesh   // about a quarter of the triangles
//
// The simplifier only removes vertices: every vertex of a level is a vertex of
// the original mesh, with its normal, uv and tangent. It works on positions
// alone, so seams (vertices repeated with other uvs or normals) do not stop it;
// across a seam a level takes the attributes of one side.

#include <stoa/geometry/Mesh.hpp>

#include <vector>

namespace stoa {

struct LodLevel {
    Mesh mesh;
    float triangleRatio = 1.0f;  // what was asked: the share of the original's triangles
    /// The simplifier's error for this level, relative to the mesh's extent
    /// (0 for level 0; 0.01 = 1% of the bounding box's size).
    float relativeError = 0.0f;
};

/// One level per entry of `triangleRatios` (each in (0, 1], decreasing; the
/// first is usually 1, the mesh itself). A level stops short of its ratio when
/// simplifying further would move the surface by more than `maxRelativeError`
/// of the mesh's extent; it never has more triangles than the level before.
/// Asserts on ratios outside (0, 1] or not decreasing, and on an empty mesh.
std::vector<LodLevel> buildLevelsOfDetail(const Mesh& mesh, const std::vector<float>& triangleRatios,
                                          float maxRelativeError = 0.05f);

} // namespace stoa
