#pragma once
// Lab 04: everything you write (tangents.cpp, height_to_normal.cpp; the lighting is
// tangent_space.glsl). docs/labs/04_normal_mapping.md derives each function. The lab's app, the
// tests and later labs include this header; your files define what it declares.

#include <stoa/geometry/Mesh.hpp>
#include <stoa/image/Image.hpp>

namespace stoa {

/// tangents.cpp: fills every vertex's `tangent` from the positions and uvs of the triangles
/// that use it. xyz: the direction in which u grows, made perpendicular to the
/// vertex normal and unit length; w = +1 or -1, chosen so that w * cross(N, T)
/// points the way v grows (w = -1 where the uvs are mirrored).
/// Needs unit normals. A vertex whose triangles give no usable uv direction
/// (all degenerate in uv) still gets a unit tangent perpendicular to its normal, w = +1.
void computeTangents(Mesh& mesh);

/// height_to_normal.cpp (docs: "From heights to normals"): a tangent-space normal map from a 1-channel
/// height map. Heights are h = value / 255; x runs along +u and rows run down
/// the image, along -v. With central differences that wrap around the borders
/// (the maps tile), the normal of texel (x, y) is
///   n = normalize(-strength * dh/du, -strength * dh/dv, 1),
/// packed into an RGB image of the same size as round((n * 0.5 + 0.5) * 255).
/// `strength` (> 0) is how many texel widths tall a height of 1 stands.
Image normalMapFromHeight(const Image& height, float strength);

} // namespace stoa
