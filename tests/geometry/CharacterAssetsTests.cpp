// Lab 10's characters (assets/crowds/*.md2 and *_skin.png): they are exactly
// what the generator writes, they load, and they have the promised size,
// animations and skins.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <Characters.hpp>

#include <stoa/core/Paths.hpp>
#include <stoa/geometry/Md2Model.hpp>
#include <stoa/image/Image.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

using namespace stoa;
namespace fs = std::filesystem;

namespace {

const fs::path committedDir = paths::assetsDir() / "crowds";

std::string readBytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

std::pair<glm::vec3, glm::vec3> bounds(const Md2Frame& frame) {
    glm::vec3 lower = frame.positions.front(), upper = lower;
    for (const glm::vec3& p : frame.positions) lower = glm::min(lower, p), upper = glm::max(upper, p);
    return {lower, upper};
}

/// The largest distance a vertex moves between two frames.
float largestMove(const Md2Frame& a, const Md2Frame& b) {
    float largest = 0.0f;
    for (std::size_t i = 0; i < a.positions.size(); ++i) largest = std::max(largest, glm::length(a.positions[i] - b.positions[i]));
    return largest;
}

} // namespace

TEST_CASE("The generator reproduces the committed characters byte for byte", "[geometry][assets][md2]") {
    test::TempFolder folder("characters");
    assets::generateCharacters(folder.path());
    for (const std::string& name : assets::characterFileNames()) {
        INFO(name << ": regenerate with bin/stoa-generate-assets --characters assets/crowds (assets/README.md)");
        REQUIRE(fs::exists(committedDir / name));
        if (fs::path(name).extension() == ".md2") {
            CHECK(readBytes(folder / name) == readBytes(committedDir / name));
        } else {
            // Pixels, not bytes: another libstb may encode the same pixels differently.
            const Image mine = Image::load(folder / name), committed = Image::load(committedDir / name);
            REQUIRE(mine.sizeInBytes() == committed.sizeInBytes());
            CHECK(std::equal(mine.data(), mine.data() + mine.sizeInBytes(), committed.data()));
            CHECK(committed.width() == 128);
            CHECK(committed.height() == 128);
            CHECK(committed.channels() == 3);
        }
    }
}

TEST_CASE("The characters load with their animations, size and skins", "[geometry][assets][md2]") {
    const std::map<std::string, std::vector<std::pair<std::string, int>>> expected{
        {"explorer", {{"stand", 4}, {"run", 8}, {"carry", 8}}},
        {"predator", {{"stand", 4}, {"run", 8}, {"attack", 8}}},
        {"prey", {{"stand", 4}, {"run", 8}, {"eat", 6}}}};
    for (const auto& [name, animations] : expected) {
        INFO(name);
        const Md2Model model = loadMd2(committedDir / (name + ".md2"));
        CHECK(model.skinNames == std::vector<std::string>{name + "_skin.png"});
        CHECK(model.skinWidth == 128);
        CHECK(model.triangles.size() <= 1200u);
        CHECK(model.triangles.size() >= 200u);
        REQUIRE(model.animations.size() == animations.size());
        for (std::size_t i = 0; i < animations.size(); ++i) {
            CHECK(model.animations[i].name == animations[i].first);
            CHECK(model.animations[i].count == animations[i].second);
        }
        const Md2Animation* stand = model.findAnimation("stand");
        const Md2Animation* run = model.findAnimation("run");
        REQUIRE(stand != nullptr);
        REQUIRE(run != nullptr);
        CHECK(model.frames[static_cast<std::size_t>(run->first)].name == "run1");

        // About 1 to 1.6 m tall or long, facing +Z, standing on y = 0 (to the encoding's step).
        const auto [lower, upper] = bounds(model.frames[static_cast<std::size_t>(stand->first)]);
        CHECK(std::max(upper.y, upper.z - lower.z) >= 0.9f);
        CHECK(std::max(upper.y, upper.z - lower.z) <= 1.7f);
        CHECK(upper.x - lower.x < upper.y);
        for (int f = 0; f < stand->count + run->count; ++f) {
            const Md2Frame& frame = model.frames[static_cast<std::size_t>(f)];
            INFO(frame.name);
            CHECK(std::abs(bounds(frame).first.y) < 0.01f);
        }
        // Every frame's triangles face the way their normals do (counter-clockwise from outside).
        for (const Md2Frame& frame : model.frames) {
            int against = 0;
            for (const Md2Triangle& t : model.triangles) {
                const glm::vec3 a = frame.positions[t.vertex[0]], b = frame.positions[t.vertex[1]], c = frame.positions[t.vertex[2]];
                const glm::vec3 normals = frame.normals[t.vertex[0]] + frame.normals[t.vertex[1]] + frame.normals[t.vertex[2]];
                if (glm::dot(glm::cross(b - a, c - a), normals) < 0.0f) ++against;
            }
            INFO(frame.name);
            CHECK(against <= static_cast<int>(model.triangles.size()) / 50);   // a few slivers may flip in 8 bits
        }
        // The run loops: its last frame is as close to its first as two neighbours are.
        const auto& frames = model.frames;
        const auto first = static_cast<std::size_t>(run->first), last = first + static_cast<std::size_t>(run->count) - 1;
        float neighbours = 0.0f;
        for (std::size_t f = first; f < last; ++f) neighbours = std::max(neighbours, largestMove(frames[f], frames[f + 1]));
        CHECK(largestMove(frames[last], frames[first]) <= neighbours * 1.05f);
        CHECK(neighbours > 0.02f);   // and it moves
        // Every texture coordinate lies on the skin.
        for (const glm::vec2& uv : model.texCoords) {
            CHECK(uv.x >= 0.0f);
            CHECK(uv.x <= 1.0f);
            CHECK(uv.y >= 0.0f);
            CHECK(uv.y <= 1.0f);
        }
    }
}

TEST_CASE("The characters' special animations do what they say", "[geometry][assets][md2]") {
    SECTION("the explorer carries its box higher than it stows it") {
        const Md2Model model = loadMd2(committedDir / "explorer.md2");
        const Md2Frame& stand = model.frames[static_cast<std::size_t>(model.findAnimation("stand")->first)];
        const Md2Frame& carry = model.frames[static_cast<std::size_t>(model.findAnimation("carry")->first)];
        CHECK(largestMove(stand, carry) > 0.1f);
    }
    SECTION("the prey's head goes down to the grass to eat") {
        const Md2Model model = loadMd2(committedDir / "prey.md2");
        const Md2Frame& stand = model.frames[static_cast<std::size_t>(model.findAnimation("stand")->first)];
        const Md2Frame& eat = model.frames[static_cast<std::size_t>(model.findAnimation("eat")->first)];
        CHECK(bounds(stand).second.y > 1.2f);
        CHECK(bounds(eat).second.y < 0.95f);
    }
    SECTION("the predator leaves the ground when it pounces") {
        const Md2Model model = loadMd2(committedDir / "predator.md2");
        const Md2Animation* attack = model.findAnimation("attack");
        REQUIRE(attack != nullptr);
        float highestLowest = 0.0f;
        for (int f = attack->first; f < attack->first + attack->count; ++f)
            highestLowest = std::max(highestLowest, bounds(model.frames[static_cast<std::size_t>(f)]).first.y);
        CHECK(highestLowest > 0.1f);
    }
}

TEST_CASE("The characters' skins paint their parts", "[geometry][assets][md2]") {
    // Islands of 32 x 32 pixels: 0 body, 2 legs, 3 eyes (Characters.cpp's Paint).
    auto at = [](const Image& skin, int island) { return skin.pixel(island % 4 * 32 + 10, island / 4 * 32 + 16); };
    const Image explorer = Image::load(committedDir / "explorer_skin.png");
    CHECK(at(explorer, 3).b > 200);   // a cyan sensor
    CHECK(at(explorer, 0).r > 150);   // a yellow body
    for (const char* name : {"predator", "prey"}) {
        INFO(name);
        const Image skin = Image::load(committedDir / (std::string(name) + "_skin.png"));
        const glm::u8vec4 body = at(skin, 0), legs = at(skin, 2);
        CHECK(int(legs.r) + legs.g + legs.b < int(body.r) + body.g + body.b);   // darker legs
    }
}
