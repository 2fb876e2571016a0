#pragma once
// The sky of lab 06: a cube map of six PNG faces (assets/sky/), a clear
// afternoon over a dusty plain with a low sun in the south-west and a few
// clouds. Faces in OpenGL's order and orientation (stoa/gl/CubeMap.hpp).

#include <stoa/image/Image.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::assets {

/// px.png, nx.png, py.png, ny.png, pz.png, nz.png.
const std::vector<std::string>& skyFileNames();
/// Face `face` (0..5: +X, -X, +Y, -Y, +Z, -Z), `size` x `size` RGB.
Image skyFace(int face, int size);
/// Writes the six faces (128 x 128) into `folder`.
void generateSky(const std::filesystem::path& folder);

} // namespace stoa::assets
