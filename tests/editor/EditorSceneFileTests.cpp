// The editor's scene files (EditorSceneFile.hpp, docs/scene-files.md), refused:
// a file that cannot be read, another version, unknown keys, values of the
// wrong type, bad ids, materials and ranges, and JSON syntax errors are each
// refused naming the file, the line of the offending value and what was
// expected. EditorSceneSaveLoadTests.cpp saves and loads valid scenes.

#include "catch.hpp"
#include "EditorSceneFileSamples.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/editor/EditorSceneFile.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace stoa;
using stoa::test::TempFolder;
namespace fs = std::filesystem;

namespace {

using stoa::test::scene_file::contains;
using stoa::test::scene_file::kScene;

/// The 1-based line of `text` where `marker` first appears.
int lineOf(const std::string& text, const std::string& marker) {
    const std::size_t at = text.find(marker);
    REQUIRE(at != std::string::npos);
    int line = 1;
    for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n';
    return line;
}

/// `text` with its one `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    REQUIRE(text.find(from, at + 1) == std::string::npos);
    return text.replace(at, from.size(), to);
}

/// The InputError editorSceneFromJson throws for `text` (read as "scene.json").
InputError errorFor(const std::string& text) {
    try {
        (void)editorSceneFromJson(text, "scene.json");
    } catch (const InputError& error) {
        return error;
    }
    FAIL("the text was accepted:\n" << text);
    return InputError("", 0, "");
}

/// Checks that `text` is refused on `line` with a message holding `part`, and
/// that what() reads "scene.json:LINE: message".
void checkRefused(const std::string& text, int line, const std::string& part) {
    const InputError error = errorFor(text);
    INFO(error.what());
    CHECK(error.file() == "scene.json");
    CHECK(error.line() == line);
    CHECK(contains(error.message(), part));
    CHECK(std::string(error.what()) == "scene.json:" + std::to_string(line) + ": " + error.message());
}

} // namespace

TEST_CASE("loadEditorScene names the file it cannot read", "[editor][scene-file]") {
    TempFolder folder("editor-scene");
    try {
        (void)loadEditorScene(folder / "none.json");
        FAIL("loaded a file that does not exist");
    } catch (const InputError& error) {
        CHECK(error.file() == (folder / "none.json").string());
        CHECK(contains(error.message(), "does not exist"));
    }
    const fs::path broken = folder.write("broken.json", "{\n  \"stoa_scene\": 1,\n  \"lights\": 5\n}\n");
    try {
        (void)loadEditorScene(broken);
        FAIL("loaded a broken file");
    } catch (const InputError& error) {
        CHECK(error.file() == broken.string());
        CHECK(error.line() == 3);
    }
}

TEST_CASE("Scene files that are not this build's are refused with their version", "[editor][scene-file]") {
    // The version is checked first: a newer file's new keys are not reported as unknown.
    const std::string newer = replaced(replaced(kScene, "\"stoa_scene\": 1", "\"stoa_scene\": 3"), "\"crowd_world\": \"\"",
                                       "\"weather\": \"rain\"");
    checkRefused(newer, 2, "written by a newer Stoa: version 3, this build reads 2");
    checkRefused(replaced(kScene, "  \"stoa_scene\": 1,\n", ""), 1, "not a Stoa scene file: no \"stoa_scene\" version");
    checkRefused(replaced(kScene, "\"stoa_scene\": 1", "\"stoa_scene\": \"1\""), 2, "\"stoa_scene\" is the format's version");
    checkRefused(replaced(kScene, "\"stoa_scene\": 1", "\"stoa_scene\": 0"), 2, "a whole number from 1");
    checkRefused(replaced(kScene, "\"stoa_scene\": 1", "\"stoa_scene\": 1.5"), 2, "a whole number from 1");
    checkRefused("\n[1, 2]\n", 2, "not a Stoa scene file: it holds an array of 2 values");
}

TEST_CASE("Unknown keys are refused with the keys allowed there", "[editor][scene-file]") {
    const std::string sun = replaced(kScene, "\"color\": [1, 1, 1]", "\"colour\": [1, 1, 1]");
    checkRefused(sun, lineOf(sun, "\"colour\""), "unknown key \"colour\" in sun; the keys allowed there are: direction, color");
    const std::string top = replaced(kScene, "\"crowd_world\": \"\"", "\"crowds\": \"\"");
    checkRefused(top, lineOf(top, "\"crowds\""),
                 "unknown key \"crowds\" in the scene; the keys allowed there are: stoa_scene, ambient, sun, camera, "
                 "renderer, crowd_world, field, light_swarm, materials, objects, lights");
    const std::string object = replaced(kScene, "\"scale\": [12, 1, 12]", "\"size\": [12, 1, 12]");
    checkRefused(object, lineOf(object, "\"size\""),
                 "unknown key \"size\" in objects[0]; the keys allowed there are: id, name, mesh, material, position, rotation, scale");
    const std::string light = replaced(kScene, "\"radius\": 6", "\"range\": 6");
    checkRefused(light, lineOf(light, "\"range\""), "in lights[0]; the keys allowed there are: id, name, position, color, radius, on");
    const std::string twice = replaced(kScene, "\"yaw\": 30,", "\"yaw\": 30,\n    \"yaw\": 40,");
    checkRefused(twice, lineOf(twice, "\"yaw\": 40"), "the key \"yaw\" is written twice in this object (first on line 11)");
}

TEST_CASE("Values of the wrong type are refused on their line", "[editor][scene-file]") {
    const std::string ambient = replaced(kScene, "\"ambient\": [0.1, 0.1, 0.1]", "\"ambient\": \"grey\"");
    checkRefused(ambient, 3, "ambient: expected an array of 3 numbers [x, y, z], found the string \"grey\"");
    const std::string two = replaced(kScene, "\"position\": [2, 1.5, -1]", "\"position\": [2, 1.5]");
    checkRefused(two, lineOf(two, "[2, 1.5]"), "objects[1].position: expected an array of 3 numbers [x, y, z], found an array of 2 values");
    // An array over several lines: the line of the item that is wrong.
    const std::string item = replaced(kScene, "\"target\": [0, 0, 0]", "\"target\": [\n      0,\n      \"up\",\n      0\n    ]");
    checkRefused(item, lineOf(item, "\"up\""), "camera.target: expected an array of 3 numbers [x, y, z], found an array holding the string \"up\"");
    const std::string flag = replaced(kScene, "\"on\": true", "\"on\": 1");
    checkRefused(flag, lineOf(flag, "\"on\": 1"), "lights[0].on: expected true or false, found the number 1");
    const std::string name = replaced(kScene, "\"name\": \"lamp\"", "\"name\": null");
    checkRefused(name, lineOf(name, "null"), "lights[0].name: expected a string \"...\", found null");
    const std::string distance = replaced(kScene, "\"distance\": 12", "\"distance\": \"12\"");
    checkRefused(distance, lineOf(distance, "\"12\""), "camera.distance: expected a number, found the string \"12\"");
    const std::string materials = replaced(kScene, "\"crowd_world\": \"\"", "\"crowd_world\": [\"a.xml\"]");
    checkRefused(materials, lineOf(materials, "[\"a.xml\"]"), "crowd_world: expected a string");
    checkRefused("{\"stoa_scene\": 1,\n\"objects\": {\"id\": 1}\n}", 2, "objects: expected an array of objects");
    const std::string huge = replaced(kScene, "\"yaw\": 30", "\"yaw\": 1e39");
    checkRefused(huge, lineOf(huge, "1e39"), "camera.yaw: 1e39 is too large for a float");
}

TEST_CASE("Issue 25: NaN, infinity, numbers too close to 0 and CR line ends get plain messages", "[editor][scene-file][issue25]") {
    const std::string nan = replaced(kScene, "\"distance\": 12", "\"distance\": nan");
    checkRefused(nan, lineOf(nan, "nan"), "'nan' is not a number JSON can hold: JSON has no NaN or infinity");
    const std::string infinity = replaced(kScene, "\"distance\": 12", "\"distance\": -Infinity");
    checkRefused(infinity, lineOf(infinity, "-Infinity"), "'-Infinity' is not a number JSON can hold");
    const std::string tiny = replaced(kScene, "\"distance\": 12", "\"distance\": 1e-60");
    checkRefused(tiny, lineOf(tiny, "1e-60"), "camera.distance: 1e-60 is too close to 0 for a float, which holds it as 0");
    // Lines ended by a CR alone (old Mac files), and CR LF: the error's line is the same.
    const std::string wrong = replaced(kScene, "\"distance\": 12", "\"distance\": oops");
    const int line = lineOf(wrong, "oops");
    std::string crOnly = wrong, crLf;
    std::replace(crOnly.begin(), crOnly.end(), '\n', '\r');
    for (char c : wrong) crLf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    checkRefused(crOnly, line, "'oops' is not a JSON value");
    checkRefused(crLf, line, "'oops' is not a JSON value");
}

TEST_CASE("Ids, materials and ranges are checked", "[editor][scene-file]") {
    const std::string twice = replaced(kScene, "\"id\": 3", "\"id\": 2");
    checkRefused(twice, lineOf(twice, "\"id\": 2,\n      \"name\": \"lamp\""),
                 "lights[0].id: id 2 is used twice, by objects[1] (\"column\", line " +
                     std::to_string(lineOf(twice, "\"id\": 2")) + ") and by lights[0] (\"lamp\")");
    const std::string zero = replaced(kScene, "\"id\": 1,", "\"id\": 0,");
    checkRefused(zero, lineOf(zero, "\"id\": 0"), "objects[0].id: ids start at 1; 0 is not an id");
    const std::string negative = replaced(kScene, "\"id\": 1,", "\"id\": -4,");
    checkRefused(negative, lineOf(negative, "\"id\": -4"),
                 "id -4 is out of range: an id is a whole number from 1 to 16777215");
    const std::string noId = replaced(kScene, "      \"id\": 1,\n", "");
    checkRefused(noId, lineOf(noId, "\"objects\": [") + 1, "objects[0]: no \"id\"");
    const std::string material = replaced(kScene, "\"material\": \"marble\"", "\"material\": \"granite\"");
    checkRefused(material, lineOf(material, "granite"),
                 "objects[1].material: no material is called \"granite\"; the materials are: marble, slate");
    const std::string sameName = replaced(kScene, "\"name\": \"slate\"", "\"name\": \"marble\"");
    checkRefused(sameName, lineOf(sameName, "\"name\": \"marble\",\n      \"shininess\": 8"),
                 "materials[1].name: \"marble\" is already the name of materials[0]");
    const std::string shininess = replaced(kScene, "\"shininess\": 32", "\"shininess\": 0");
    checkRefused(shininess, lineOf(shininess, "\"shininess\": 0"), "materials[0].shininess: must be greater than 0");
    const std::string negativeShininess = replaced(kScene, "\"shininess\": 8", "\"shininess\": -2.5");
    checkRefused(negativeShininess, lineOf(negativeShininess, "-2.5"), "materials[1].shininess: must be greater than 0 (the Blinn-Phong exponent), found -2.5");
    const std::string radius = replaced(kScene, "\"radius\": 6", "\"radius\": 0");
    checkRefused(radius, lineOf(radius, "\"radius\": 0"), "lights[0].radius: must be greater than 0");
    const std::string pcf = replaced(kScene, "\"pcf\": 3", "\"pcf\": 4");
    checkRefused(pcf, lineOf(pcf, "\"pcf\": 4"), "renderer.pcf: expected 1, 3 or 5 (the shadow filter's width in texels), found the number 4");
    const std::string pcfFloat = replaced(kScene, "\"pcf\": 3", "\"pcf\": 3.0");
    checkRefused(pcfFloat, lineOf(pcfFloat, "\"pcf\": 3.0"), "renderer.pcf: expected 1, 3 or 5");
    const std::string shape = replaced(kScene, "\"shape:plane\"", "\"shape:torus\"");
    checkRefused(shape, lineOf(shape, "shape:torus"), "objects[0].mesh: unknown shape \"shape:torus\"");
    const std::string diffuse = replaced(kScene, "\"diffuse\": [0.8, 0.8, 0.8]", "\"diffuse\": [0.8, 1.2, 0.8]");
    checkRefused(diffuse, lineOf(diffuse, "1.2"), "materials[0].diffuse: a colour's components are from 0 to 1");
    const std::string sun = replaced(kScene, "\"direction\": [-0.4, -1, -0.3]", "\"direction\": [0, 0, 0]");
    checkRefused(sun, lineOf(sun, "\"direction\""), "sun.direction: must not be [0, 0, 0]");
    const std::string control = replaced(kScene, "\"name\": \"lamp\"", "\"name\": \"la\\u0000mp\"");
    checkRefused(control, lineOf(control, "la\\u0000mp"), "lights[0].name: a control character");
}

TEST_CASE("The field and the light swarm of version 2 are checked", "[editor][scene-file]") {
    const std::string v2 = replaced(replaced(kScene, "\"stoa_scene\": 1", "\"stoa_scene\": 2"), "\"crowd_world\": \"\"",
                                    "\"crowd_world\": \"\",\n  \"field\": {\"meshes\": [\"shape:cube\"], \"material\": \"marble\", "
                                    "\"rows\": 4, \"spacing\": 3, \"clear_radius\": 2, \"seed\": 1},\n  \"light_swarm\": "
                                    "{\"count\": 10, \"radius\": 5, \"height\": 2, \"brightness\": 1.5, \"seed\": 2}");
    const EditorScene scene = editorSceneFromJson(v2, "scene.json");
    CHECK(scene.field.meshes == std::vector<std::string>{"shape:cube"});
    CHECK(scene.field.rows == 4);
    CHECK(scene.lightSwarm.count == 10);
    CHECK(scene.lightSwarm.brightness == 1.5f);
    const std::string rows = replaced(v2, "\"rows\": 4", "\"rows\": 0");
    checkRefused(rows, lineOf(rows, "\"rows\": 0"), "field.rows: expected a whole number from 1 to 100 (copies per side; 100 x 100 draw in 1.8 "
                 "times the showcase's frame on a 2-core machine with llvmpipe), found the number 0");
    const std::string material = replaced(v2, "\"material\": \"marble\", \"rows\"", "\"material\": \"gold\", \"rows\"");
    checkRefused(material, lineOf(material, "gold"), "field.material: no material is called \"gold\"");
    const std::string meshes = replaced(v2, "[\"shape:cube\"]", "\"shape:cube\"");
    checkRefused(meshes, lineOf(meshes, "\"meshes\""), "field.meshes: expected an array of asset names");
    const std::string count = replaced(v2, "\"count\": 10", "\"count\": 5000");
    checkRefused(count, lineOf(count, "5000"), "light_swarm.count: expected a whole number from 0 to 2000 (how many lights; 2000 draw in 1.9 "
                 "times the showcase's frame on a 2-core machine with llvmpipe), found the number 5000");
    // The cap itself loads; one more is refused.
    CHECK(editorSceneFromJson(replaced(v2, "\"count\": 10", "\"count\": 2000"), "scene.json").lightSwarm.count ==
          stoa::EditorLightSwarm::kMaxCount);
    const std::string overCap = replaced(v2, "\"count\": 10", "\"count\": 2001");
    checkRefused(overCap, lineOf(overCap, "2001"), "light_swarm.count: expected a whole number from 0 to 2000");
    const std::string height = replaced(v2, "\"height\": 2", "\"height\": 0.1");
    checkRefused(height, lineOf(height, "\"height\": 0.1"), "light_swarm.height: must be 0.3 or more");
    const std::string pcf = replaced(v2, "\"pcf\": 3", "\"pcf\": 5");
    checkRefused(pcf, lineOf(pcf, "\"pcf\": 5"), "renderer.pcf: expected a whole number from 1 to 3 (lab 05's shadow filter");
    const std::string shape = replaced(v2, "[\"shape:cube\"]", "[\"shape:cone\"]");
    checkRefused(shape, lineOf(shape, "shape:cone"), "field.meshes[0]: unknown shape \"shape:cone\"");
    // Version 2's keys in a file that says version 1.
    const std::string old = replaced(v2, "\"stoa_scene\": 2", "\"stoa_scene\": 1");
    checkRefused(old, lineOf(old, "\"field\""), "field: new in version 2 of the format, but the file says \"stoa_scene\": 1");
    const std::string oldSky = replaced(kScene, "\"ssao\": false,", "\"ssao\": false,\n    \"sky\": false,");
    checkRefused(oldSky, lineOf(oldSky, "\"sky\""), "renderer.sky: new in version 2 of the format");
    const std::string key = replaced(v2, "\"seed\": 2", "\"speed\": 2");
    checkRefused(key, lineOf(key, "\"speed\""), "unknown key \"speed\" in light_swarm; the keys allowed there are: count, radius, height, brightness, seed");
}

TEST_CASE("JSON syntax errors name the line and say plainly what is wrong", "[editor][scene-file]") {
    const std::string trailing = replaced(kScene, "\"shininess\": 8\n", "\"shininess\": 8,\n");
    checkRefused(trailing, lineOf(trailing, "\"shininess\": 8,") + 1, "a ',' before '}': JSON allows no comma after an object's last member");
    const std::string trailingItem = replaced(kScene, "\"on\": true\n    }\n", "\"on\": true\n    },\n");
    checkRefused(trailingItem, lineOf(trailingItem, "    },\n  ]") + 1, "a ',' before ']'");
    const std::string comma = replaced(kScene, "\"yaw\": 30,", "\"yaw\": 30");
    checkRefused(comma, lineOf(comma, "\"pitch\""), "a missing ',' before a string (after the value that ends on line 11)");
    const std::string commaInArray = replaced(kScene, "[1.5, 1.2, 0.9]", "[1.5, 1.2\n        0.9]");
    checkRefused(commaInArray, lineOf(commaInArray, "0.9]"), "a missing ',' before a number");
    const std::string colon = replaced(kScene, "\"yaw\": 30", "\"yaw\" 30");
    checkRefused(colon, lineOf(colon, "\"yaw\" 30"), "a missing ':' after the key");
    const std::string noValue = replaced(kScene, "\"yaw\": 30,", "\"yaw\": ,");
    checkRefused(noValue, lineOf(noValue, "\"yaw\""), "no value after \"yaw\":");
    const std::string unclosed = kScene.substr(0, kScene.rfind('}'));
    checkRefused(unclosed, static_cast<int>(std::count(unclosed.begin(), unclosed.end(), '\n')), "the file ends before the object that starts on line 1 is closed (a missing '}')");
    const std::string lineBreak = replaced(kScene, "\"name\": \"lamp\"", "\"name\": \"lamp\n");
    checkRefused(lineBreak, lineOf(lineBreak, "\"lamp"), "a line break inside a string");
    const std::string comment = replaced(kScene, "\"ambient\"", "// the light everywhere\n  \"ambient\"");
    checkRefused(comment, lineOf(comment, "//"), "a comment: JSON has no comments");
    const std::string quotes = replaced(kScene, "\"debug_view\": \"final\"", "'debug_view': 'final'");
    checkRefused(quotes, lineOf(quotes, "'debug_view'"), "a single quote");
    const std::string bare = replaced(kScene, "\"on\": true", "\"on\": yes");
    checkRefused(bare, lineOf(bare, "yes"), "'yes' is not a JSON value");
    const std::string capital = replaced(kScene, "\"on\": true", "\"on\": True");
    checkRefused(capital, lineOf(capital, "True"), "is not a JSON value");
    const std::string number = replaced(kScene, "\"yaw\": 30", "\"yaw\": 30.");
    checkRefused(number, lineOf(number, "30."), "is not a number");
    const std::string escape = replaced(kScene, "\"acropolis/column_diffuse.png\"", "\"acropolis\\column_diffuse.png\"");
    checkRefused(escape, lineOf(escape, "acropolis\\c"), "an unknown escape in a string");
    checkRefused(kScene + "{}\n", lineOf(kScene + "{}\n", "{}"), "text after the end of the file's value, which ends on line");
    checkRefused("", 1, "the file is empty");
    checkRefused("  \n\n", 1, "the file is empty");
    checkRefused("{\"stoa_scene\": 1, \"yaw\": 1e400}", 1, "the number '1e400' is too large");
    // nlohmann would stop at a NUL byte and never see what follows it.
    checkRefused(std::string("{\"stoa_scene\": 1}\n\n") + '\0' + "garbage", 3, "a NUL byte");
    checkRefused("{\"stoa_scene\": 1,\n\"name\": \"\xff\"}", 2, "bytes that are not UTF-8 text");
    std::string deep = "{\"stoa_scene\": 1,\n\"crowd_world\": ";
    for (int i = 0; i < 100; ++i) deep += "[";
    checkRefused(deep, 2, "nested more than 32 deep");
    // A byte order mark is no error.
    CHECK(editorSceneFromJson("\xEF\xBB\xBF{\"stoa_scene\": 1}", "scene.json").objects.empty());
}

TEST_CASE("An id past EditorScene::kMaxId is refused with the file, its line, the id and the range",
          "[editor][scene-file]") {
    // 4294967295 used to load, and the editor's next spawn wrapped to id 0,
    // which it saved and could not open again.
    TempFolder folder("editor-scene");
    const std::string huge = replaced(kScene, "\"id\": 3", "\"id\": 4294967295");
    const fs::path file = folder.write("huge.json", huge);
    try {
        (void)loadEditorScene(file);
        FAIL("loaded an id the editor cannot follow");
    } catch (const InputError& error) {
        CHECK(error.file() == file.string());
        CHECK(error.line() == lineOf(huge, "4294967295"));
        CHECK(std::string(error.what()) == file.string() + ":" + std::to_string(lineOf(huge, "4294967295")) +
                                               ": lights[0].id: id 4294967295 is out of range: an id is a whole number "
                                               "from 1 to 16777215");
    }
    const std::string past = replaced(kScene, "\"id\": 3", "\"id\": 16777216");
    checkRefused(past, lineOf(past, "16777216"), "lights[0].id: id 16777216 is out of range");
    const std::string endless = replaced(kScene, "\"id\": 3", "\"id\": 123456789012345678901234567890");
    checkRefused(endless, lineOf(endless, "1234567"), "lights[0].id: expected a whole number from 1 to 16777215");
    CHECK(EditorScene::kMaxId == 16777215u);
    const std::string largest = replaced(kScene, "\"id\": 3", "\"id\": 16777215");
    CHECK(editorSceneFromJson(largest, "scene.json").lights[0].id == EditorScene::kMaxId);
}
