#pragma once
// Quake 2 MD2 models: a triangle mesh stored as a sequence of key frames (every
// frame holds every vertex, compressed to three bytes plus an index into a
// fixed table of 162 normals), texture coordinates in skin pixels and named
// animations spelt by the frames' names ("run1", "run2", ... make "run").
// No OpenGL here; lab 10 blends two frames (StudentCode::crowds).
//
//   Md2Model robot = loadMd2(assetsDir() / "crowds/explorer.md2");
//   const Md2Animation* run = robot.findAnimation("run");

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace stoa {

/// One key frame, decompressed: positions in model units (scale * byte + translate)
/// and unit normals from the table, one of each per vertex.
struct Md2Frame {
    std::string name;                 // at most 15 characters
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
};

/// A triangle: three vertex indices (into every frame) and three texture
/// coordinate indices (into Md2Model::texCoords), counter-clockwise from the front.
struct Md2Triangle {
    std::array<std::uint16_t, 3> vertex{};
    std::array<std::uint16_t, 3> texCoord{};
};

/// Consecutive frames whose names share a prefix before their trailing digits.
struct Md2Animation {
    std::string name;
    int first = 0;    // index of its first frame
    int count = 0;    // how many frames
};

struct Md2Model {
    int skinWidth = 0, skinHeight = 0;        // pixels
    std::vector<std::string> skinNames;       // as stored (often a Quake path); Stoa's worlds name the skin themselves
    std::vector<glm::vec2> texCoords;         // normalized, v up (OpenGL convention: s / width, 1 - t / height)
    std::vector<Md2Triangle> triangles;
    std::vector<Md2Frame> frames;
    std::vector<Md2Animation> animations;     // in frame order

    std::size_t vertexCount() const { return frames.empty() ? 0 : frames.front().positions.size(); }
    /// The animation with that name, or nullptr.
    const Md2Animation* findAnimation(const std::string& name) const;
};

/// The format's fixed table of 162 unit normals that a vertex's normal index
/// points into: the corners of an icosahedron whose faces were cut into 16
/// and pushed out onto the unit sphere (10 * 4^2 + 2 = 162), the same point
/// set as id Software's table, built at start-up with the same bits on every
/// machine. Its order is Stoa's own (id's cannot be rebuilt from a rule), so
/// files written by encodeMd2() round-trip, but a third-party MD2 file's
/// normals decode to other directions of the set: recompute them from its
/// triangles (Md2Model.cpp explains).
const std::array<glm::vec3, 162>& md2NormalTable();

/// The table index of the normal closest to `normal` (the encoder's choice).
int nearestMd2Normal(const glm::vec3& normal);

struct Md2Limits {
    static constexpr std::size_t maxFileBytes = 16u << 20;
    static constexpr int maxVertices = 2048;     // Quake 2's own limits
    static constexpr int maxTriangles = 4096;
    static constexpr int maxFrames = 512;
    static constexpr int maxSkins = 32;
    static constexpr int maxTexCoords = 3 * maxTriangles;   // one per triangle corner at most
    /// How far from the origin a frame may put a vertex (|scale| x 255 + |translate|
    /// on each axis), in model units: finite is not enough, as 3e38 x 255 is not.
    static constexpr float maxCoordinate = 1.0e6f;
};

/// Reads an MD2 file. Throws InputError naming the file and what was wrong:
/// too short for a header, a wrong magic number ("IDP2") or version (8), a
/// count that is negative or past Md2Limits, an offset or a block that lies
/// outside the file, a frame size that does not match the vertex count, a
/// triangle that indexes a vertex or texture coordinate that does not exist,
/// a normal index >= 162, a skin size of zero. Also refused: a model without
/// a vertex, a texture coordinate, a triangle or a frame; a frame's scale or
/// translation that is not finite; a frame name without a NUL within its 16
/// bytes or with a byte that is not printable ASCII. GL commands are not read
/// (their block only has to lie inside the file). Animations group consecutive
/// frames by their names without trailing digits ("run1".."run6" make "run").
Md2Model loadMd2(const std::filesystem::path& path);
/// The same for a file in memory; `name` is the file named in errors.
Md2Model decodeMd2(const std::uint8_t* bytes, std::size_t size, const std::string& name);

/// Writes `model` as an MD2 file's bytes: each frame's positions compressed
/// to 8 bits per axis over that frame's bounds, normals to table indices,
/// texture coordinates to skin pixels. The asset generator and the tests use it.
/// A decoded position lies within half a step (the frame's extent / 255 / 2 per
/// axis) of the original. Skin names, frame names and counts must fit the
/// format (std::invalid_argument otherwise: a programming error, not input).
std::string encodeMd2(const Md2Model& model);

} // namespace stoa
