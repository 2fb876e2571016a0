#pragma once
// The Acropolis scene of labs 03-05, after the proof-of-concept scene of seed
// 002 (a temple, a statue, a limiting wall, columns): the generated meshes and
// textures of assets/acropolis/ (assets/README.md) placed on a stone floor. Units are
// metres, +Y is up, the floor is y = 0 and a camera at +Z looking towards -Z
// sees the front of everything:
//
//                 temple, pediment towards +Z      (z = -13 .. -4)
//   wall    c   c   c   c   c   c   (columns, z = -1.5)
//   (x=-10,                              statue on its pedestal (x = 6.5, z = 3)
//   facing +X)
//   ------------------ floor 30 m x 30 m, centred on the origin ------------------
//
// Meshes are loaded once per process and uploaded once per context: building
// the scene again (each case) reuses them. Destroy a scene before the context
// its meshes were uploaded in.

#include <stoa/geometry/Mesh.hpp>
#include <stoa/geometry/ObjLoader.hpp>
#include <stoa/scene/Light.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/mat4x4.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace stoa {

/// Which objects buildAcropolisScene() adds, and how. The defaults give the whole scene.
struct AcropolisOptions {
    bool floor = true;
    bool columns = true;
    bool wall = true;
    bool temple = true;
    bool statue = true;    // the statue and its pedestal
    int columnCount = 6;   // 1..12, in a row along X, 2.5 m apart, centred on x = 0
    /// When set, every mesh goes through it before upload (lab 03's facet
    /// normals, lab 04's tangents). Such meshes are uploaded afresh on every
    /// build and not shared with builds that use no filter (or another one).
    std::function<Mesh(const Mesh&)> meshFilter;
};

/// Clears `scene` and fills it with the objects `options` asks for, named
/// "floor", "column 1".."column N", "wall", "temple", "pedestal" and "statue",
/// each with its material from acropolis.mtl (the pedestal uses "marble").
/// Sets scene.ambient to a soft sky (0.15) and adds acropolisSun(); the lab may
/// replace the lights. Needs a current context. Throws InputError when an asset
/// file is missing or malformed.
void buildAcropolisScene(Scene& scene, const AcropolisOptions& options = {});

/// The axis-aligned bounds (min, max) in world metres of the objects `options`
/// includes, e.g. to fit a shadow map's orthographic box. With the floor they
/// span x, z in [-15, 15]; y runs from 0 to the temple's ridge (7.3 m).
/// Loads the meshes (once per process) but needs no GL context.
std::pair<glm::vec3, glm::vec3> acropolisBounds(const AcropolisOptions& options = {});

/// One object of the scene as data, without GL: what buildAcropolisScene()
/// adds, for code that works on the CPU (lab 07's ray casting). An object with
/// several materials is several pieces of one name.
struct AcropolisPiece {
    std::string name;            // "floor", "column 1", ..., as buildAcropolisScene() names them
    const Mesh* mesh = nullptr;  // object space; loaded once, kept until the process ends
    Material material;
    glm::mat4 model{1.0f};       // object -> world, as Object::modelMatrix() makes it
};

/// The pieces of the objects `options` includes, in buildAcropolisScene()'s
/// order. Loads the meshes (once per process) but needs no GL context; ignores
/// options.meshFilter.
std::vector<AcropolisPiece> acropolisPieces(const AcropolisOptions& options = {});

/// acropolisPieces() with an avenue of six more statues on lower pedestals,
/// three each side of the path from the front of the floor towards the columns
/// (x = -3.2 and 3.2, z = 2 to 9), turned to face it, named "statue 2" ..
/// "statue 7": about 304,000 triangles, the scale of labs 08-09's deferred
/// renderer. Needs no GL context.
std::vector<AcropolisPiece> acropolisAvenuePieces();

/// The late-afternoon sun the scene is lit with by default: low from the front
/// right, so the columns throw long shadows back towards the temple steps.
DirectionalLight acropolisSun();

/// How many meshes buildAcropolisScene() has uploaded in this process: a
/// rebuild that reuses the meshes leaves it unchanged (the tests check this).
std::size_t acropolisUploadCount();

/// The model loaded from assetsDir()/acropolis/`fileName` (e.g. "statue.obj"),
/// read once per process and kept until it ends. Throws InputError as loadObj().
const Model& acropolisModel(const std::string& fileName);

} // namespace stoa
