#pragma once
// The animated characters of lab 10 (assets/crowds/): Quake 2 MD2 models built
// from simple parts (boxes, tapered cylinders, ellipsoids), each part moved
// rigidly per frame (legs swing about the hip, a head nods about the neck),
// and a 128 x 128 RGB skin whose uv islands paint the parts. Units are
// metres, +Y is up, the characters face +Z and stand on y = 0.
//
//   explorer  a wheeled robot with a sensor head and a sample box: stand, run, carry
//   predator  a wolf-like quadruped: stand, run, attack
//   prey      a deer-like quadruped: stand, run, eat
//
// Every animation's frames are named name1..nameN; a run is a gait cycle whose
// last frame leads back into the first. Only + - * / and the generator's
// portable sin and cos are used, so the files are the same bits everywhere.

#include <stoa/geometry/Md2Model.hpp>
#include <stoa/image/Image.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace stoa::assets {

/// explorer.md2, explorer_skin.png, predator.md2, predator_skin.png, prey.md2, prey_skin.png.
const std::vector<std::string>& characterFileNames();

/// The characters by name ("explorer", "predator", "prey"); each names its
/// skin "NAME_skin.png" (Md2Model::skinNames).
Md2Model characterModel(const std::string& name);
/// The skin of that character: 128 x 128 RGB.
Image characterSkin(const std::string& name);

/// Writes the six files into `folder` (created if needed).
void generateCharacters(const std::filesystem::path& folder);

} // namespace stoa::assets
