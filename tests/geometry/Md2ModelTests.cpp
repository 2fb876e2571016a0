// Lab 10's MD2 models: encodeMd2 -> decodeMd2 keeps what the format keeps
// (positions within half a quantisation step, normals as their nearest table
// entry, texture coordinates in whole skin pixels, animations from the frame
// names), and every malformed file is refused with an InputError that names
// the problem (the same cases are in the fuzzers' regression corpus,
// tests/fuzz/make-regression-corpus.py).

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/geometry/Md2Model.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <string>

using namespace stoa;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The header's int32 fields, in file order.
enum Field { kIdent, kVersion, kSkinWidth, kSkinHeight, kFrameSize, kSkins, kVertices, kTexCoords, kTriangles,
             kGlCommands, kFrames, kSkinsAt, kTexCoordsAt, kTrianglesAt, kFramesAt, kGlCommandsAt, kEnd };

std::int32_t field(const std::string& bytes, Field which) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[4 * which + i]);
    std::int32_t result;
    std::memcpy(&result, &value, 4);
    return result;
}

void put32(std::string& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
}

std::string withField(std::string bytes, Field which, std::int32_t value) {
    put32(bytes, 4 * static_cast<std::size_t>(which), static_cast<std::uint32_t>(value));
    return bytes;
}

/// A unit-ish tetrahedron with 4 vertices, 4 triangles, 6 texture
/// coordinates on a 64 x 32 skin, and frames stand1..2, run1..3, pain (the
/// vertices move from frame to frame).
Md2Model smallModel() {
    Md2Model model;
    model.skinWidth = 64;
    model.skinHeight = 32;
    model.skinNames = {"models/test/skin.pcx"};
    for (int i = 0; i < 6; ++i) model.texCoords.emplace_back((i * 9 + 1) / 64.0f, 1.0f - (i * 5 + 2) / 32.0f);
    const std::uint16_t faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    for (int i = 0; i < 4; ++i) {
        Md2Triangle triangle;
        for (int corner = 0; corner < 3; ++corner) {
            triangle.vertex[corner] = faces[i][corner];
            triangle.texCoord[corner] = static_cast<std::uint16_t>((i + corner) % 6);
        }
        model.triangles.push_back(triangle);
    }
    const char* names[] = {"stand1", "stand2", "run1", "run2", "run3", "pain"};
    for (int f = 0; f < 6; ++f) {
        Md2Frame frame;
        frame.name = names[f];
        const float lift = 0.1f * f;
        frame.positions = {{0.0f, lift, 0.0f}, {1.0f, lift, 0.0f}, {0.0f, 1.0f + lift, 0.3f * f}, {0.2f, 0.4f, 1.0f + lift}};
        for (const glm::vec3& position : frame.positions) frame.normals.push_back(glm::normalize(position - glm::vec3(0.3f, 0.5f, 0.4f)));
        model.frames.push_back(frame);
    }
    return model;
}

Md2Model decode(const std::string& bytes) {
    return decodeMd2(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), "test.md2");
}

/// The message of the InputError decoding `bytes` throws.
std::string errorOf(const std::string& bytes) {
    try {
        (void)decode(bytes);
    } catch (const InputError& error) {
        CHECK(error.file() == "test.md2");
        CHECK(error.line() == 0);
        return error.message();
    }
    FAIL("decodeMd2 accepted the bytes");
    return "";
}

} // namespace

TEST_CASE("The MD2 normal table: 162 distinct unit normals, evenly spread", "[geometry][md2]") {
    const auto& table = md2NormalTable();
    float closest = 2.0f;   // the largest dot product between two entries
    for (std::size_t i = 0; i < table.size(); ++i) {
        CHECK(glm::length(table[i]) == Approx(1.0f).margin(1e-6));
        CHECK(nearestMd2Normal(table[i]) == static_cast<int>(i));
        for (std::size_t j = 0; j < i; ++j) closest = std::min(closest, 1.0f - glm::dot(table[i], table[j]));
    }
    CHECK(closest > 1.0f - std::cos(0.24f));   // no two entries within about 14 degrees (14.5 is the least)
    // Every direction has an entry within 11 degrees (the corners' spacing is about 18).
    for (int i = 0; i < 500; ++i) {
        const float z = -1.0f + 2.0f * (static_cast<float>(i) + 0.5f) / 500.0f;
        const float angle = 2.399963f * static_cast<float>(i);   // a Fibonacci spiral over the sphere
        const float radius = std::sqrt(1.0f - z * z);
        const glm::vec3 direction(radius * std::cos(angle), radius * std::sin(angle), z);
        CHECK(glm::dot(direction, table[static_cast<std::size_t>(nearestMd2Normal(direction))]) > std::cos(11.0f * 3.14159265f / 180.0f));
    }
    // The same point set as id's table: the entries quoted in public discussions of the
    // format (Md2Model.cpp) are in it, to their six decimals (only the order differs).
    for (const glm::vec3 quoted : {glm::vec3(-0.525731f, 0.0f, 0.850651f), glm::vec3(-0.442863f, 0.238856f, 0.864188f),
                                   glm::vec3(-0.295242f, 0.0f, 0.955423f), glm::vec3(-0.309017f, 0.5f, 0.809017f)}) {
        const glm::vec3 entry = table[static_cast<std::size_t>(nearestMd2Normal(quoted))];
        CHECK(glm::length(entry - quoted) < 2e-6f);
    }
}

TEST_CASE("An MD2 model survives encodeMd2 and decodeMd2", "[geometry][md2]") {
    const Md2Model original = smallModel();
    const std::string bytes = encodeMd2(original);
    CHECK(field(bytes, kIdent) == 844121161);
    CHECK(bytes.substr(0, 4) == "IDP2");
    CHECK(field(bytes, kVersion) == 8);
    CHECK(field(bytes, kFrameSize) == 40 + 4 * 4);
    CHECK(field(bytes, kEnd) == static_cast<std::int32_t>(bytes.size()));
    const Md2Model decoded = decode(bytes);

    CHECK(decoded.skinWidth == 64);
    CHECK(decoded.skinHeight == 32);
    CHECK(decoded.skinNames == original.skinNames);
    CHECK(decoded.vertexCount() == 4);
    REQUIRE(decoded.texCoords.size() == original.texCoords.size());
    for (std::size_t i = 0; i < decoded.texCoords.size(); ++i) {
        // Whole pixels survive exactly: s / 64 and 1 - t / 32 are exact in float.
        CHECK(decoded.texCoords[i] == original.texCoords[i]);
    }
    REQUIRE(decoded.triangles.size() == original.triangles.size());
    for (std::size_t i = 0; i < decoded.triangles.size(); ++i) {
        CHECK(decoded.triangles[i].vertex == original.triangles[i].vertex);
        CHECK(decoded.triangles[i].texCoord == original.triangles[i].texCoord);
    }
    REQUIRE(decoded.frames.size() == original.frames.size());
    for (std::size_t f = 0; f < decoded.frames.size(); ++f) {
        const Md2Frame& in = original.frames[f];
        const Md2Frame& out = decoded.frames[f];
        INFO("frame " << in.name);
        CHECK(out.name == in.name);
        glm::vec3 lower = in.positions[0], upper = lower;
        for (const glm::vec3& p : in.positions) lower = glm::min(lower, p), upper = glm::max(upper, p);
        const glm::vec3 halfStep = (upper - lower) / 255.0f / 2.0f + 1e-6f;
        for (std::size_t v = 0; v < in.positions.size(); ++v) {
            for (int axis = 0; axis < 3; ++axis) CHECK(std::abs(out.positions[v][axis] - in.positions[v][axis]) <= halfStep[axis]);
            CHECK(out.normals[v] == md2NormalTable()[static_cast<std::size_t>(nearestMd2Normal(in.normals[v]))]);
            CHECK(glm::dot(out.normals[v], in.normals[v]) > 0.98f);
        }
    }
    REQUIRE(decoded.animations.size() == 3);
    CHECK(decoded.animations[0].name == "stand");
    CHECK(decoded.animations[0].first == 0);
    CHECK(decoded.animations[0].count == 2);
    CHECK(decoded.animations[1].name == "run");
    CHECK(decoded.animations[1].first == 2);
    CHECK(decoded.animations[1].count == 3);
    CHECK(decoded.animations[2].name == "pain");
    CHECK(decoded.animations[2].count == 1);
    CHECK(decoded.findAnimation("run") == &decoded.animations[1]);
    CHECK(decoded.findAnimation("walk") == nullptr);

    // Encoding the decoded model gives the same bytes: the round trip is stable.
    CHECK(encodeMd2(decoded) == bytes);
}

TEST_CASE("loadMd2 reads a file and names it in errors", "[geometry][md2]") {
    test::TempFolder folder("md2");
    const fs::path good = folder.write("good.md2", encodeMd2(smallModel()));
    CHECK(loadMd2(good).frames.size() == 6);
    const fs::path bad = folder.write("bad.md2", "IDP2");
    try {
        (void)loadMd2(bad);
        FAIL("expected InputError");
    } catch (const InputError& error) {
        CHECK(error.file() == bad.string());
        CHECK(contains(error.message(), "too short"));
    }
    CHECK_THROWS_AS(loadMd2(folder.path()), InputError);             // a folder
    CHECK_THROWS_AS(loadMd2(folder / "missing.md2"), InputError);
}

TEST_CASE("Malformed MD2 files are refused with a message that names the problem", "[geometry][md2]") {
    const std::string good = encodeMd2(smallModel());
    const std::int32_t framesAt = field(good, kFramesAt), trianglesAt = field(good, kTrianglesAt);
    const std::int32_t frameSize = field(good, kFrameSize);

    SECTION("truncated header") {
        CHECK(contains(errorOf(good.substr(0, 67)), "too short for an MD2 file: 67 bytes"));
        CHECK(contains(errorOf(""), "too short"));
    }
    SECTION("truncated file: the header's end lies past it") {
        CHECK(contains(errorOf(good.substr(0, good.size() - 10)), "file ends at byte"));
    }
    SECTION("truncated frame block") {
        const std::int32_t cut = framesAt + 2 * frameSize + 10;   // in the middle of frame 2
        const std::string message = errorOf(withField(withField(good.substr(0, cut), kEnd, cut), kGlCommands, 0));
        CHECK(contains(message, "4 vertices per frame but frame 2 ends past the end of the file"));
        CHECK(contains(message, "of " + std::to_string(cut) + ")"));
    }
    SECTION("bad magic") {
        std::string bytes = good;
        bytes[3] = '3';
        CHECK(contains(errorOf(bytes), "expected the magic number \"IDP2\""));
    }
    SECTION("bad version") { CHECK(contains(errorOf(withField(good, kVersion, 7)), "version 7; expected version 8")); }
    SECTION("negative counts") {
        for (Field count : {kSkins, kVertices, kTexCoords, kTriangles, kFrames, kGlCommands}) {
            INFO("field " << count);
            CHECK(contains(errorOf(withField(good, count, -1)), "negative number of"));
        }
        CHECK(contains(errorOf(withField(good, kFrames, std::numeric_limits<std::int32_t>::min())), "negative number of frames"));
    }
    SECTION("counts past the limits") {
        CHECK(contains(errorOf(withField(good, kFrames, 513)), "513 frames, more than the 512"));
        CHECK(contains(errorOf(withField(good, kVertices, 2049)), "2,049 vertices per frame, more than the 2,048"));
        CHECK(contains(errorOf(withField(good, kTriangles, 4097)), "4,097 triangles, more than the 4,096"));
        CHECK(contains(errorOf(withField(good, kSkins, 33)), "33 skins, more than the 32"));
        CHECK(contains(errorOf(withField(good, kVertices, 0)), "needs at least 1"));
        CHECK(contains(errorOf(withField(good, kFrames, 0)), "0 frames"));
    }
    SECTION("offsets out of range or overlapping the end") {
        CHECK(contains(errorOf(withField(good, kTexCoordsAt, 1000000000)), "texture coordinates (6 x 4 bytes from byte 1,000,000,000)"));
        CHECK(contains(errorOf(withField(good, kTrianglesAt, static_cast<std::int32_t>(good.size()) - 20)), "triangles"));
        CHECK(contains(errorOf(withField(good, kTrianglesAt, static_cast<std::int32_t>(good.size()) - 20)), "past the end of the file"));
        CHECK(contains(errorOf(withField(good, kSkinsAt, -68)), "negative offset (-68) for the skin names"));
        CHECK(contains(errorOf(withField(good, kTrianglesAt, 8)), "inside the 68-byte header"));
        CHECK(contains(errorOf(withField(good, kGlCommandsAt, 2147483647)), "GL commands"));
        CHECK(contains(errorOf(withField(good, kFramesAt, 2147483647)), "frame 0 ends past the end of the file"));
        CHECK(contains(errorOf(withField(good, kEnd, 2147483647)), "file ends at byte 2,147,483,647"));
        CHECK(contains(errorOf(withField(good, kEnd, -1)), "file ends at byte -1"));
    }
    SECTION("frame size mismatch") {
        CHECK(contains(errorOf(withField(good, kFrameSize, frameSize + 4)), "frame size of 60 bytes, but 4 vertices per frame take 40 + 4 x 4 = 56"));
        CHECK(contains(errorOf(withField(good, kVertices, 5)), "frame size of 56 bytes"));
    }
    SECTION("a triangle indexes a vertex or texture coordinate that does not exist") {
        std::string bytes = good;
        bytes[static_cast<std::size_t>(trianglesAt) + 12 + 2] = 4;   // triangle 1, corner 1's vertex
        CHECK(contains(errorOf(bytes), "triangle 1 names vertex 4, but a frame has 4 vertices (0 to 3)"));
        bytes = good;
        bytes[static_cast<std::size_t>(trianglesAt) + 6] = 6;   // triangle 0, corner 0's texture coordinate
        CHECK(contains(errorOf(bytes), "triangle 0 names texture coordinate 6, but the file has 6 (0 to 5)"));
    }
    SECTION("a normal index past the table") {
        std::string bytes = good;
        bytes[static_cast<std::size_t>(framesAt + frameSize) + 40 + 4 * 2 + 3] = static_cast<char>(162);
        CHECK(contains(errorOf(bytes), "frame 1 gives vertex 2 normal index 162"));
    }
    SECTION("zero or negative skin size") {
        CHECK(contains(errorOf(withField(good, kSkinWidth, 0)), "skin size of 0 x 32"));
        CHECK(contains(errorOf(withField(good, kSkinHeight, -5)), "skin size of 64 x -5"));
    }
    SECTION("non-finite scale or translation") {
        std::string bytes = good;
        put32(bytes, static_cast<std::size_t>(framesAt) + 4, 0x7F800000u);   // frame 0, scale.y = infinity
        CHECK(contains(errorOf(bytes), "frame 0 has a scale or translation that is not a finite number"));
        bytes = good;
        put32(bytes, static_cast<std::size_t>(framesAt + 3 * frameSize) + 16, 0x7FC00000u);   // frame 3, translate.y = NaN
        CHECK(contains(errorOf(bytes), "frame 3 has a scale or translation"));
    }
    SECTION("a finite scale or translation that puts vertices at 3e38 x 255 (issue 25)") {
        std::string bytes = good;
        put32(bytes, static_cast<std::size_t>(framesAt) + 4, 0x7F61B1E6u);   // frame 0, scale.y = 3e38
        CHECK(contains(errorOf(bytes), "frame 0's y axis (scale 3e+38, translation"));
        CHECK(contains(errorOf(bytes), "expected at most 1e+06"));
        bytes = good;
        put32(bytes, static_cast<std::size_t>(framesAt + 2 * frameSize) + 12, 0x7F61B1E6u);   // frame 2, translate.x = 3e38
        CHECK(contains(errorOf(bytes), "frame 2's x axis"));
    }
    SECTION("a skin name of 64 bytes without a NUL, or with a control byte (issue 25)") {
        const std::int32_t skinsAt = field(good, kSkinsAt);
        std::string bytes = good;
        for (int i = 0; i < 64; ++i) bytes[static_cast<std::size_t>(skinsAt + i)] = 'a';
        CHECK(contains(errorOf(bytes), "MD2 skin name 0 has no NUL byte within its 64 bytes"));
        bytes = good;
        bytes[static_cast<std::size_t>(skinsAt + 3)] = '\t';
        CHECK(contains(errorOf(bytes), "MD2 skin name 0 holds the control byte 9 at position 3"));
    }
    SECTION("frame names without a NUL or with bytes that are not printable") {
        std::string bytes = good;
        for (int i = 0; i < 16; ++i) bytes[static_cast<std::size_t>(framesAt) + 24 + i] = 'a';
        CHECK(contains(errorOf(bytes), "frame 0's name \"aaaaaaaaaaaaaaaa\" has no NUL byte within its 16 bytes"));
        bytes = good;
        bytes[static_cast<std::size_t>(framesAt + frameSize) + 24 + 2] = '\n';
        CHECK(contains(errorOf(bytes), "frame 1's name holds byte 10 at position 2"));
    }
}

TEST_CASE("encodeMd2 refuses a model the format cannot hold", "[geometry][md2]") {
    Md2Model model = smallModel();
    model.frames[1].name = "a-name-longer-than-15";
    CHECK_THROWS_AS(encodeMd2(model), std::invalid_argument);
    model = smallModel();
    model.frames[2].positions.pop_back();
    CHECK_THROWS_AS(encodeMd2(model), std::invalid_argument);
    model = smallModel();
    model.triangles[0].vertex[1] = 9;
    CHECK_THROWS_AS(encodeMd2(model), std::invalid_argument);
    CHECK_THROWS_AS(encodeMd2(Md2Model{}), std::invalid_argument);
}
