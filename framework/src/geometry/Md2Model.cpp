#include <stoa/geometry/Md2Model.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <utility>

// The MD2 layout (little-endian throughout):
//
//   header   68 bytes: 17 int32 (see Header below)
//   skins    num_skins x char[64]
//   st       num_st x (int16 s, int16 t), in skin pixels, t down
//   tris     num_tris x (uint16 vertex[3], uint16 st[3])
//   frames   num_frames x framesize bytes: float scale[3], float translate[3],
//            char name[16], then num_vertices x (uint8 v[3], uint8 normalIndex)
//   glcmds   num_glcmds x int32 (triangle strips and fans for Quake's GL
//            renderer; Stoa draws the triangles and only checks where they lie)
//
// Every value is read byte by byte (no casts of the buffer to wider types, so
// no unaligned or aliasing reads) and every offset is computed in 64 bits, so
// a header with the largest int32 values cannot wrap an address around.

namespace stoa {

namespace {

constexpr std::int32_t kIdent = 844121161;   // "IDP2" read as a little-endian int32
constexpr std::int32_t kVersion = 8;
constexpr std::int64_t kHeaderBytes = 68;
constexpr std::int64_t kSkinNameBytes = 64;
constexpr std::int64_t kTexCoordBytes = 4;
constexpr std::int64_t kTriangleBytes = 12;
constexpr std::int64_t kFrameHeaderBytes = 40;
constexpr std::int64_t kFrameNameBytes = 16;
constexpr std::int64_t kVertexBytes = 4;

std::uint32_t readU32(const std::uint8_t* bytes, std::int64_t at) {
    return static_cast<std::uint32_t>(bytes[at]) | static_cast<std::uint32_t>(bytes[at + 1]) << 8 |
           static_cast<std::uint32_t>(bytes[at + 2]) << 16 | static_cast<std::uint32_t>(bytes[at + 3]) << 24;
}

std::int32_t readI32(const std::uint8_t* bytes, std::int64_t at) {
    const std::uint32_t bits = readU32(bytes, at);
    std::int32_t value;
    std::memcpy(&value, &bits, sizeof value);   // two's complement, without implementation-defined conversion
    return value;
}

std::uint16_t readU16(const std::uint8_t* bytes, std::int64_t at) {
    return static_cast<std::uint16_t>(bytes[at] | bytes[at + 1] << 8);
}

std::int16_t readI16(const std::uint8_t* bytes, std::int64_t at) {
    const std::uint16_t bits = readU16(bytes, at);
    std::int16_t value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

float readF32(const std::uint8_t* bytes, std::int64_t at) {
    const std::uint32_t bits = readU32(bytes, at);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

/// 12345678 -> "12,345,678", for byte positions in messages.
std::string withCommas(std::int64_t value) {
    std::string digits = std::to_string(value < 0 ? -value : value);
    for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(static_cast<std::size_t>(at), ",");
    return value < 0 ? "-" + digits : digits;
}

/// The header's fields in file order.
struct Header {
    std::int32_t ident, version, skinWidth, skinHeight, frameSize, skinCount, vertexCount, texCoordCount,
        triangleCount, glCommandCount, frameCount, skinsOffset, texCoordsOffset, trianglesOffset, framesOffset,
        glCommandsOffset, endOffset;
};

Header readHeader(const std::uint8_t* bytes) {
    std::int32_t fields[17];
    for (int i = 0; i < 17; ++i) fields[i] = readI32(bytes, 4 * i);
    return {fields[0], fields[1], fields[2], fields[3], fields[4], fields[5], fields[6], fields[7], fields[8],
            fields[9], fields[10], fields[11], fields[12], fields[13], fields[14], fields[15], fields[16]};
}

/// "frame 3", "frames" etc. are the callers' words; this checks one count.
void checkCount(const std::string& name, const char* what, std::int32_t count, int minimum, std::int64_t maximum) {
    if (count < 0)
        throw InputError(name, 0, "MD2 header gives a negative number of " + std::string(what) + " (" +
                                      std::to_string(count) + "); expected " +
                                      (minimum > 0 ? "at least " + std::to_string(minimum) : std::string("0 or more")));
    if (count < minimum)
        throw InputError(name, 0, "MD2 header gives " + std::to_string(count) + " " + what + "; a model needs at least " +
                                      std::to_string(minimum));
    if (count > maximum)
        throw InputError(name, 0, "MD2 header gives " + withCommas(count) + " " + what + ", more than the " +
                                      withCommas(maximum) + " an MD2 model may have");
}

/// A block of `count` records of `recordBytes` bytes at `offset` must lie
/// between the header and the end the header states.
void checkBlock(const std::string& name, const char* what, std::int32_t offset, std::int64_t count,
                std::int64_t recordBytes, std::int64_t end) {
    if (offset < 0)
        throw InputError(name, 0, "MD2 header gives a negative offset (" + std::to_string(offset) + ") for the " + what);
    if (count == 0) return;
    if (offset < kHeaderBytes)
        throw InputError(name, 0, "MD2 header puts the " + std::string(what) + " at byte " + std::to_string(offset) +
                                      ", inside the 68-byte header");
    const std::int64_t blockEnd = std::int64_t{offset} + count * recordBytes;   // at most 2^31 + 2^31 * 2^15: no overflow
    if (blockEnd > end)
        throw InputError(name, 0, "MD2 header says the " + std::string(what) + " (" + withCommas(count) + " x " +
                                      std::to_string(recordBytes) + " bytes from byte " + withCommas(offset) +
                                      ") end at byte " + withCommas(blockEnd) + ", past the end of the file (byte " +
                                      withCommas(end) + ")");
}

/// A frame's name: printable ASCII ended by a NUL within its 16 bytes.
std::string frameName(const std::uint8_t* bytes, std::int64_t at, int frame, const std::string& name) {
    std::string result;
    for (std::int64_t i = 0; i < kFrameNameBytes; ++i) {
        const std::uint8_t byte = bytes[at + i];
        if (byte == 0) return result;
        if (byte < 0x20 || byte > 0x7E)
            throw InputError(name, 0, "MD2 frame " + std::to_string(frame) + "'s name holds byte " + std::to_string(byte) +
                                          " at position " + std::to_string(i) + "; expected printable ASCII ended by a NUL");
        result += static_cast<char>(byte);
    }
    throw InputError(name, 0, "MD2 frame " + std::to_string(frame) + "'s name \"" + quoteInput(result) +
                                  "\" has no NUL byte within its 16 bytes");
}

/// "run12" -> "run": the animation a frame belongs to.
std::string animationName(const std::string& frameName) {
    std::size_t end = frameName.size();
    while (end > 0 && frameName[end - 1] >= '0' && frameName[end - 1] <= '9') --end;
    return frameName.substr(0, end);
}

// The normal table. Quake 2 stores a vertex normal as an index into 162
// directions that cover the sphere about evenly: the corners of a geodesic
// sphere of frequency 4, that is an icosahedron whose every flat triangle was
// cut into 16 (each edge into four equal parts) and whose cut points were
// pushed out onto the unit sphere; 10 * 4^2 + 2 = 162. Stoa builds that point
// set here, with the icosahedron in the position whose corners are the cyclic
// permutations of (+-1, 0, +-phi): the entries of id's table that are quoted
// in public discussions of the format (-0.525731 0 0.850651, -0.442863
// 0.238856 0.864188, -0.295242 0 0.955423, -0.309017 0.5 0.809017) are, to
// their six decimals, the corner A = (-1, 0, phi), (3A + C) / 4, (3A + B) / 4
// and (A + C) / 2 of its face A = (-1, 0, phi), B = (1, 0, phi), C = (0, phi, 1),
// normalized. What cannot be rebuilt from a rule is the order of id's table
// (its values are under the GPL and are not copied here), so Stoa's indices
// follow its own order: the 12 corners, then the points on the 30 edges, then
// those inside the 20 faces, as they are met. Only + - * / and sqrt are used
// (IEEE 754 rounds each exactly), so every machine builds the same bits.
// Consequence: files written by encodeMd2() round-trip exactly, but a
// third-party MD2 file's normal indices count in id's order and decode to
// other directions of the same set; recompute such a model's normals from its
// triangles (positions, texture coordinates and animations are unaffected).
std::array<glm::vec3, 162> buildNormalTable() {
    struct Point { double x, y, z; };
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    const Point corners[12] = {
        {-1, 0, phi}, {1, 0, phi}, {-1, 0, -phi}, {1, 0, -phi},
        {0, phi, 1}, {0, phi, -1}, {0, -phi, 1}, {0, -phi, -1},
        {phi, 1, 0}, {-phi, 1, 0}, {phi, -1, 0}, {-phi, -1, 0}};
    // The 20 faces: every three corners at the edge length (2) from each other.
    std::vector<std::array<int, 3>> faces;
    auto adjacent = [&](int a, int b) {
        const double dx = corners[a].x - corners[b].x, dy = corners[a].y - corners[b].y, dz = corners[a].z - corners[b].z;
        return std::abs(dx * dx + dy * dy + dz * dz - 4.0) < 1e-9;
    };
    for (int a = 0; a < 12; ++a)
        for (int b = a + 1; b < 12; ++b)
            for (int c = b + 1; c < 12; ++c)
                if (adjacent(a, b) && adjacent(b, c) && adjacent(a, c)) faces.push_back({a, b, c});
    // A point of a face is a weighting of its corners in quarters, (i A + j B + k C) / 4
    // with i + j + k = 4; it is named by its nonzero (corner, weight) pairs, sorted, so that
    // a point on an edge or at a corner is made once for all the faces that share it.
    using Key = std::vector<std::pair<int, int>>;
    std::map<Key, int> made;
    std::vector<std::pair<int, Point>> points;   // (0 corner, 1 edge, 2 inside a face) and the direction
    for (const auto& face : faces) {
        for (int i = 0; i <= 4; ++i) {
            for (int j = 0; i + j <= 4; ++j) {
                const int weights[3] = {i, j, 4 - i - j};
                Key key;
                Point sum{0, 0, 0};
                for (int corner = 0; corner < 3; ++corner) {
                    if (weights[corner] == 0) continue;
                    key.emplace_back(face[corner], weights[corner]);
                    const Point& p = corners[face[corner]];
                    sum = {sum.x + weights[corner] * p.x, sum.y + weights[corner] * p.y, sum.z + weights[corner] * p.z};
                }
                std::sort(key.begin(), key.end());
                if (!made.emplace(key, 0).second) continue;
                const double length = std::sqrt(sum.x * sum.x + sum.y * sum.y + sum.z * sum.z);
                points.emplace_back(static_cast<int>(key.size()) - 1, Point{sum.x / length, sum.y / length, sum.z / length});
            }
        }
    }
    std::stable_sort(points.begin(), points.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
    std::array<glm::vec3, 162> table{};
    for (std::size_t i = 0; i < table.size(); ++i) {
        const Point& p = points.at(i).second;
        table[i] = glm::vec3(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
    }
    return table;
}

void requireForEncode(bool condition, const std::string& what) {
    if (!condition) throw std::invalid_argument("encodeMd2(): " + what);
}

void writeU8(std::string& out, std::uint32_t value) { out += static_cast<char>(static_cast<unsigned char>(value & 0xFF)); }
void writeU16(std::string& out, std::uint32_t value) {
    writeU8(out, value);
    writeU8(out, value >> 8);
}
void writeI32(std::string& out, std::int64_t value) {
    const auto bits = static_cast<std::uint32_t>(value);
    writeU16(out, bits & 0xFFFF);
    writeU16(out, bits >> 16);
}
void writeF32(std::string& out, float value) {
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    writeU16(out, bits & 0xFFFF);
    writeU16(out, bits >> 16);
}
void writeName(std::string& out, const std::string& name, std::size_t bytes) {
    out += name;
    out.append(bytes - name.size(), '\0');
}

bool printableAscii(const std::string& text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return c >= 0x20 && c <= 0x7E; });
}

/// The skin pixel of a normalized, v-up texture coordinate, clamped to int16.
std::int32_t toPixel(float coordinate, int size) {
    const double pixel = std::floor(static_cast<double>(coordinate) * size + 0.5);
    if (!(pixel >= -32768.0)) return -32768;   // also NaN
    return pixel > 32767.0 ? 32767 : static_cast<std::int32_t>(pixel);
}

} // namespace

const std::array<glm::vec3, 162>& md2NormalTable() {
    static const std::array<glm::vec3, 162> table = buildNormalTable();
    return table;
}

int nearestMd2Normal(const glm::vec3& normal) {
    const auto& table = md2NormalTable();
    int best = 0;
    float bestDot = -2.0f;
    for (int i = 0; i < static_cast<int>(table.size()); ++i) {
        const float dot = glm::dot(table[static_cast<std::size_t>(i)], normal);
        if (dot > bestDot) {
            bestDot = dot;
            best = i;
        }
    }
    return best;
}

const Md2Animation* Md2Model::findAnimation(const std::string& name) const {
    for (const Md2Animation& animation : animations)
        if (animation.name == name) return &animation;
    return nullptr;
}

Md2Model loadMd2(const std::filesystem::path& path) {
    const std::string bytes = readInputFile(path, Md2Limits::maxFileBytes, "MD2 file");
    return decodeMd2(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), path.string());
}

Md2Model decodeMd2(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
    if (size < static_cast<std::size_t>(kHeaderBytes))
        throw InputError(name, 0, "too short for an MD2 file: " + std::to_string(size) +
                                      " bytes, and the header alone takes 68");
    if (size > Md2Limits::maxFileBytes)
        throw InputError(name, 0, "MD2 file of " + withCommas(static_cast<std::int64_t>(size)) +
                                      " bytes, more than the " + withCommas(Md2Limits::maxFileBytes) + " Stoa reads");
    const Header header = readHeader(bytes);
    if (header.ident != kIdent)
        throw InputError(name, 0, "not an MD2 file: expected the magic number \"IDP2\" in its first 4 bytes, found \"" +
                                      std::string(reinterpret_cast<const char*>(bytes), 4) + "\"");
    if (header.version != kVersion)
        throw InputError(name, 0, "MD2 header gives version " + std::to_string(header.version) +
                                      "; expected version 8 (Quake 2's)");
    if (header.skinWidth <= 0 || header.skinHeight <= 0)
        throw InputError(name, 0, "MD2 header gives a skin size of " + std::to_string(header.skinWidth) + " x " +
                                      std::to_string(header.skinHeight) + " pixels; expected both above zero");
    checkCount(name, "skins", header.skinCount, 0, Md2Limits::maxSkins);
    checkCount(name, "vertices per frame", header.vertexCount, 1, Md2Limits::maxVertices);
    checkCount(name, "texture coordinates", header.texCoordCount, 1, Md2Limits::maxTexCoords);
    checkCount(name, "triangles", header.triangleCount, 1, Md2Limits::maxTriangles);
    checkCount(name, "frames", header.frameCount, 1, Md2Limits::maxFrames);
    checkCount(name, "GL commands", header.glCommandCount, 0, static_cast<std::int64_t>(Md2Limits::maxFileBytes / 4));
    const std::int64_t frameBytes = kFrameHeaderBytes + kVertexBytes * header.vertexCount;
    if (header.frameSize != frameBytes)
        throw InputError(name, 0, "MD2 header gives a frame size of " + std::to_string(header.frameSize) + " bytes, but " +
                                      std::to_string(header.vertexCount) + " vertices per frame take 40 + 4 x " +
                                      std::to_string(header.vertexCount) + " = " + std::to_string(frameBytes));
    if (header.endOffset < 0 || static_cast<std::uint64_t>(header.endOffset) > size)
        throw InputError(name, 0, "MD2 header says the file ends at byte " + withCommas(header.endOffset) +
                                      ", but the file has " + withCommas(static_cast<std::int64_t>(size)) + " bytes");
    const std::int64_t end = header.endOffset;
    checkBlock(name, "skin names", header.skinsOffset, header.skinCount, kSkinNameBytes, end);
    checkBlock(name, "texture coordinates", header.texCoordsOffset, header.texCoordCount, kTexCoordBytes, end);
    checkBlock(name, "triangles", header.trianglesOffset, header.triangleCount, kTriangleBytes, end);
    checkBlock(name, "GL commands", header.glCommandsOffset, header.glCommandCount, 4, end);
    if (header.framesOffset < kHeaderBytes)
        checkBlock(name, "frames", header.framesOffset, header.frameCount, frameBytes, end);   // throws
    for (std::int64_t frame = 0; frame < header.frameCount; ++frame) {
        const std::int64_t frameEnd = header.framesOffset + (frame + 1) * frameBytes;
        if (frameEnd > end)
            throw InputError(name, 0, "MD2 header says " + withCommas(header.vertexCount) + " vertices per frame but frame " +
                                          std::to_string(frame) + " ends past the end of the file (byte " +
                                          withCommas(frameEnd) + " of " + withCommas(end) + ")");
    }

    Md2Model model;
    model.skinWidth = header.skinWidth;
    model.skinHeight = header.skinHeight;
    for (std::int64_t skin = 0; skin < header.skinCount; ++skin) {
        const char* text = reinterpret_cast<const char*>(bytes + header.skinsOffset + skin * kSkinNameBytes);
        const char* end = std::find(text, text + kSkinNameBytes, '\0');
        if (end == text + kSkinNameBytes)
            throw InputError(name, 0, "MD2 skin name " + std::to_string(skin) + " has no NUL byte within its 64 bytes");
        const auto control = std::find_if(text, end, [](char c) { return static_cast<unsigned char>(c) < 0x20; });
        if (control != end)
            throw InputError(name, 0, "MD2 skin name " + std::to_string(skin) + " holds the control byte " +
                                          std::to_string(static_cast<int>(*control)) + " at position " +
                                          std::to_string(control - text));
        model.skinNames.emplace_back(text, end);
    }
    model.texCoords.reserve(static_cast<std::size_t>(header.texCoordCount));
    for (std::int64_t i = 0; i < header.texCoordCount; ++i) {
        const std::int64_t at = header.texCoordsOffset + i * kTexCoordBytes;
        const float s = readI16(bytes, at), t = readI16(bytes, at + 2);
        model.texCoords.emplace_back(s / static_cast<float>(header.skinWidth), 1.0f - t / static_cast<float>(header.skinHeight));
    }
    model.triangles.reserve(static_cast<std::size_t>(header.triangleCount));
    for (std::int64_t i = 0; i < header.triangleCount; ++i) {
        const std::int64_t at = header.trianglesOffset + i * kTriangleBytes;
        Md2Triangle triangle;
        for (int corner = 0; corner < 3; ++corner) {
            triangle.vertex[corner] = readU16(bytes, at + 2 * corner);
            triangle.texCoord[corner] = readU16(bytes, at + 6 + 2 * corner);
            if (triangle.vertex[corner] >= header.vertexCount)
                throw InputError(name, 0, "MD2 triangle " + std::to_string(i) + " names vertex " +
                                              std::to_string(triangle.vertex[corner]) + ", but a frame has " +
                                              std::to_string(header.vertexCount) + " vertices (0 to " +
                                              std::to_string(header.vertexCount - 1) + ")");
            if (triangle.texCoord[corner] >= header.texCoordCount)
                throw InputError(name, 0, "MD2 triangle " + std::to_string(i) + " names texture coordinate " +
                                              std::to_string(triangle.texCoord[corner]) + ", but the file has " +
                                              std::to_string(header.texCoordCount) + " (0 to " +
                                              std::to_string(header.texCoordCount - 1) + ")");
        }
        model.triangles.push_back(triangle);
    }

    const auto& normals = md2NormalTable();
    model.frames.reserve(static_cast<std::size_t>(header.frameCount));
    for (int frame = 0; frame < header.frameCount; ++frame) {
        const std::int64_t at = header.framesOffset + frame * frameBytes;
        glm::vec3 scale, translate;
        for (int axis = 0; axis < 3; ++axis) {
            scale[axis] = readF32(bytes, at + 4 * axis);
            translate[axis] = readF32(bytes, at + 12 + 4 * axis);
        }
        for (int axis = 0; axis < 3; ++axis) {
            if (!std::isfinite(scale[axis]) || !std::isfinite(translate[axis]))
                throw InputError(name, 0, "MD2 frame " + std::to_string(frame) + " has a scale or translation that is not a "
                                              "finite number (infinity or NaN)");
            const double reach = std::abs(double{scale[axis]}) * 255.0 + std::abs(double{translate[axis]});
            if (reach > Md2Limits::maxCoordinate) {
                char text[160];
                std::snprintf(text, sizeof text, "MD2 frame %d's %c axis (scale %g, translation %g) places vertices up to %g "
                              "units from the origin; expected at most %g", frame, "xyz"[axis], double{scale[axis]},
                              double{translate[axis]}, reach, double{Md2Limits::maxCoordinate});
                throw InputError(name, 0, text);
            }
        }
        Md2Frame decoded;
        decoded.name = frameName(bytes, at + 24, frame, name);
        decoded.positions.reserve(static_cast<std::size_t>(header.vertexCount));
        decoded.normals.reserve(static_cast<std::size_t>(header.vertexCount));
        for (std::int64_t vertex = 0; vertex < header.vertexCount; ++vertex) {
            const std::int64_t v = at + kFrameHeaderBytes + vertex * kVertexBytes;
            const int normalIndex = bytes[v + 3];
            if (normalIndex >= static_cast<int>(normals.size()))
                throw InputError(name, 0, "MD2 frame " + std::to_string(frame) + " gives vertex " + std::to_string(vertex) +
                                              " normal index " + std::to_string(normalIndex) +
                                              "; expected an index into the 162 normals (0 to 161)");
            decoded.positions.emplace_back(scale.x * bytes[v] + translate.x, scale.y * bytes[v + 1] + translate.y,
                                           scale.z * bytes[v + 2] + translate.z);
            decoded.normals.push_back(normals[static_cast<std::size_t>(normalIndex)]);
        }
        const std::string animation = animationName(decoded.name);
        if (model.animations.empty() || model.animations.back().name != animation)
            model.animations.push_back({animation, frame, 0});
        ++model.animations.back().count;
        model.frames.push_back(std::move(decoded));
    }
    return model;
}

std::string encodeMd2(const Md2Model& model) {
    requireForEncode(!model.frames.empty(), "the model has no frames; give it at least one");
    const std::size_t vertexCount = model.vertexCount();
    requireForEncode(vertexCount >= 1 && vertexCount <= static_cast<std::size_t>(Md2Limits::maxVertices),
                     "a frame has " + std::to_string(vertexCount) + " vertices; expected 1 to 2048");
    requireForEncode(!model.triangles.empty() && model.triangles.size() <= static_cast<std::size_t>(Md2Limits::maxTriangles),
                     std::to_string(model.triangles.size()) + " triangles; expected 1 to 4096");
    requireForEncode(!model.texCoords.empty() && model.texCoords.size() <= static_cast<std::size_t>(Md2Limits::maxTexCoords),
                     std::to_string(model.texCoords.size()) + " texture coordinates; expected 1 to 12288");
    requireForEncode(model.frames.size() <= static_cast<std::size_t>(Md2Limits::maxFrames),
                     std::to_string(model.frames.size()) + " frames; expected at most 512");
    requireForEncode(model.skinNames.size() <= static_cast<std::size_t>(Md2Limits::maxSkins),
                     std::to_string(model.skinNames.size()) + " skin names; expected at most 32");
    requireForEncode(model.skinWidth > 0 && model.skinHeight > 0, "the skin size must be above zero; set skinWidth and skinHeight");
    for (const std::string& skin : model.skinNames)
        requireForEncode(skin.size() < kSkinNameBytes && skin.find('\0') == std::string::npos,
                         "skin name \"" + skin + "\" must be shorter than 64 bytes, without NUL");
    for (const Md2Frame& frame : model.frames) {
        requireForEncode(frame.positions.size() == vertexCount && frame.normals.size() == vertexCount,
                         "frame \"" + frame.name + "\" must have as many positions and normals as the first frame (" +
                             std::to_string(vertexCount) + ")");
        for (const glm::vec3& position : frame.positions)
            requireForEncode(std::isfinite(position.x) && std::isfinite(position.y) && std::isfinite(position.z),
                             "frame \"" + frame.name + "\" has a position that is not finite");
        requireForEncode(frame.name.size() < kFrameNameBytes && printableAscii(frame.name),
                         "frame name \"" + frame.name + "\" must be printable ASCII of at most 15 characters");
    }
    for (const Md2Triangle& triangle : model.triangles) {
        for (int corner = 0; corner < 3; ++corner) {
            requireForEncode(triangle.vertex[corner] < vertexCount, "a triangle names vertex " +
                                                                        std::to_string(triangle.vertex[corner]) + " of " +
                                                                        std::to_string(vertexCount));
            requireForEncode(triangle.texCoord[corner] < model.texCoords.size(),
                             "a triangle names texture coordinate " + std::to_string(triangle.texCoord[corner]) + " of " +
                                 std::to_string(model.texCoords.size()));
        }
    }

    const std::int64_t frameBytes = kFrameHeaderBytes + kVertexBytes * static_cast<std::int64_t>(vertexCount);
    const std::int64_t skinsOffset = kHeaderBytes;
    const std::int64_t texCoordsOffset = skinsOffset + kSkinNameBytes * static_cast<std::int64_t>(model.skinNames.size());
    const std::int64_t trianglesOffset = texCoordsOffset + kTexCoordBytes * static_cast<std::int64_t>(model.texCoords.size());
    const std::int64_t framesOffset = trianglesOffset + kTriangleBytes * static_cast<std::int64_t>(model.triangles.size());
    const std::int64_t glCommandsOffset = framesOffset + frameBytes * static_cast<std::int64_t>(model.frames.size());
    const std::int64_t endOffset = glCommandsOffset + 4;   // one GL command: the 0 that ends an empty list

    std::string out;
    out.reserve(static_cast<std::size_t>(endOffset));
    for (const std::int64_t field :
         {std::int64_t{kIdent}, std::int64_t{kVersion}, std::int64_t{model.skinWidth}, std::int64_t{model.skinHeight},
          frameBytes, static_cast<std::int64_t>(model.skinNames.size()), static_cast<std::int64_t>(vertexCount),
          static_cast<std::int64_t>(model.texCoords.size()), static_cast<std::int64_t>(model.triangles.size()),
          std::int64_t{1}, static_cast<std::int64_t>(model.frames.size()), skinsOffset, texCoordsOffset, trianglesOffset,
          framesOffset, glCommandsOffset, endOffset})
        writeI32(out, field);
    for (const std::string& skin : model.skinNames) writeName(out, skin, kSkinNameBytes);
    for (const glm::vec2& uv : model.texCoords) {
        writeU16(out, static_cast<std::uint32_t>(toPixel(uv.x, model.skinWidth)));
        writeU16(out, static_cast<std::uint32_t>(toPixel(1.0f - uv.y, model.skinHeight)));
    }
    for (const Md2Triangle& triangle : model.triangles) {
        for (const std::uint16_t index : triangle.vertex) writeU16(out, index);
        for (const std::uint16_t index : triangle.texCoord) writeU16(out, index);
    }
    for (const Md2Frame& frame : model.frames) {
        // Each axis spans the frame's bounds in 255 steps: position = scale * byte + translate.
        glm::vec3 lower = frame.positions.front(), upper = lower;
        for (const glm::vec3& position : frame.positions) {
            lower = glm::min(lower, position);
            upper = glm::max(upper, position);
        }
        const glm::vec3 scale = (upper - lower) / 255.0f;
        for (int axis = 0; axis < 3; ++axis) writeF32(out, scale[axis]);
        for (int axis = 0; axis < 3; ++axis) writeF32(out, lower[axis]);
        writeName(out, frame.name, kFrameNameBytes);
        for (std::size_t vertex = 0; vertex < vertexCount; ++vertex) {
            for (int axis = 0; axis < 3; ++axis) {
                const float steps = scale[axis] > 0.0f ? (frame.positions[vertex][axis] - lower[axis]) / scale[axis] : 0.0f;
                writeU8(out, static_cast<std::uint32_t>(std::clamp(std::floor(steps + 0.5f), 0.0f, 255.0f)));
            }
            writeU8(out, static_cast<std::uint32_t>(nearestMd2Normal(frame.normals[vertex])));
        }
    }
    writeI32(out, 0);
    return out;
}

} // namespace stoa
