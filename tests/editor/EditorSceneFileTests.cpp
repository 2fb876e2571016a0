// The editor's scene files (EditorSceneFile.hpp, docs/scene-files.md): every
// field survives a save and a load, a second save gives the same bytes, a
// frozen version-1 file and the example scene load, saving never leaves a
// half-written file, and each mistake in a file is refused naming the file,
// the line of the offending value and what was expected.

#include "catch.hpp"
#include "TempFolder.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/editor/EditorSceneFile.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

using namespace stoa;
using stoa::test::TempFolder;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

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

// A valid scene every refusal below changes in one place.
const std::string kScene = R"({
  "stoa_scene": 1,
  "ambient": [0.1, 0.1, 0.1],
  "sun": {
    "direction": [-0.4, -1, -0.3],
    "color": [1, 1, 1]
  },
  "camera": {
    "target": [0, 0, 0],
    "distance": 12,
    "yaw": 30,
    "pitch": 25
  },
  "renderer": {
    "deferred": false,
    "shadows": true,
    "pcf": 3,
    "normal_maps": true,
    "ssao": false,
    "debug_view": "final"
  },
  "crowd_world": "",
  "materials": [
    {
      "name": "marble",
      "diffuse": [0.8, 0.8, 0.8],
      "specular": [0.2, 0.2, 0.2],
      "shininess": 32,
      "diffuse_map": "acropolis/column_diffuse.png",
      "normal_map": "",
      "shader": ""
    },
    {
      "name": "slate",
      "shininess": 8
    }
  ],
  "objects": [
    {
      "id": 1,
      "name": "floor",
      "mesh": "shape:plane",
      "material": "slate",
      "position": [0, 0, 0],
      "rotation": [0, 0, 0],
      "scale": [12, 1, 12]
    },
    {
      "id": 2,
      "name": "column",
      "mesh": "shape:cylinder",
      "material": "marble",
      "position": [2, 1.5, -1]
    }
  ],
  "lights": [
    {
      "id": 3,
      "name": "lamp",
      "position": [0, 3, 0],
      "color": [1.5, 1.2, 0.9],
      "radius": 6,
      "on": true
    }
  ]
}
)";

/// A scene with no field at its default, for the round trip.
EditorScene fullScene() {
    EditorScene scene;
    scene.ambient = {0.11f, 0.12f, 0.13f};
    scene.sunDirection = {-0.25f, -1.0f, 0.5f};
    scene.sunColor = {0.9f, 0.8f, 0.7f};
    scene.crowdWorld = "crowds/explorers.xml";
    scene.renderer.deferred = true;
    scene.renderer.shadows = false;
    scene.renderer.pcfSize = 2;
    scene.renderer.normalMaps = false;
    scene.renderer.ssao = true;
    scene.renderer.debugView = "albedo";
    scene.renderer.sky = false;
    scene.renderer.culling = false;
    scene.field.meshes = {"acropolis/column.obj", "shape:cube"};
    scene.field.rows = 7;
    scene.field.spacing = 12.5f;
    scene.field.clearRadius = 0.0f;
    scene.field.seed = 42;
    scene.lightSwarm.count = 128;
    scene.lightSwarm.radius = 9.5f;
    scene.lightSwarm.height = 1.25f;
    scene.lightSwarm.brightness = 0.75f;
    scene.lightSwarm.seed = 3;
    scene.camera.target = {1.0f, 2.0f, 3.0f};
    scene.camera.distance = 7.25f;
    scene.camera.yawDegrees = -135.0f;
    scene.camera.pitchDegrees = 60.5f;
    EditorMaterial marble;
    marble.name = "marble \"polished\"";
    marble.diffuse = {0.9f, 0.85f, 0.8f};
    marble.specular = {0.5f, 0.6f, 0.7f};
    marble.shininess = 96.0f;
    marble.diffuseMap = "acropolis/column_diffuse.png";
    marble.normalMap = "textures/marble_normal.png";
    marble.shader = "editor/lit";
    scene.materials.push_back(marble);
    EditorMaterial plain;
    plain.name = "plain";
    scene.materials.push_back(plain);
    EditorObject& column = scene.addObject("column", "acropolis/column.obj", marble.name);
    column.position = {-2.5f, 0.0f, 1.0f / 3.0f};
    column.rotationDegrees = {10.0f, 20.0f, -30.0f};
    column.scale = {0.5f, 2.0f, 0.5f};
    scene.addObject("box", "shape:cube", "plain").id = 7;
    EditorLight lamp;
    lamp.id = 9;
    lamp.name = "lamp \\ back";
    lamp.position = {1.0f, 4.0f, -2.0f};
    lamp.color = {3.0f, 2.5f, 0.1f};
    lamp.radius = 12.5f;
    lamp.on = false;
    scene.lights.push_back(lamp);
    return scene;
}

void checkSame(const glm::vec3& a, const glm::vec3& b) {
    CHECK(a.x == b.x);
    CHECK(a.y == b.y);
    CHECK(a.z == b.z);
}

void checkSameScene(const EditorScene& a, const EditorScene& b) {
    checkSame(a.ambient, b.ambient);
    checkSame(a.sunDirection, b.sunDirection);
    checkSame(a.sunColor, b.sunColor);
    CHECK(a.crowdWorld == b.crowdWorld);
    CHECK(a.renderer.deferred == b.renderer.deferred);
    CHECK(a.renderer.shadows == b.renderer.shadows);
    CHECK(a.renderer.pcfSize == b.renderer.pcfSize);
    CHECK(a.renderer.normalMaps == b.renderer.normalMaps);
    CHECK(a.renderer.ssao == b.renderer.ssao);
    CHECK(a.renderer.debugView == b.renderer.debugView);
    CHECK(a.renderer.sky == b.renderer.sky);
    CHECK(a.renderer.culling == b.renderer.culling);
    CHECK(a.field.meshes == b.field.meshes);
    CHECK(a.field.material == b.field.material);
    CHECK(a.field.rows == b.field.rows);
    CHECK(a.field.spacing == b.field.spacing);
    CHECK(a.field.clearRadius == b.field.clearRadius);
    CHECK(a.field.seed == b.field.seed);
    CHECK(a.lightSwarm.count == b.lightSwarm.count);
    CHECK(a.lightSwarm.radius == b.lightSwarm.radius);
    CHECK(a.lightSwarm.height == b.lightSwarm.height);
    CHECK(a.lightSwarm.brightness == b.lightSwarm.brightness);
    CHECK(a.lightSwarm.seed == b.lightSwarm.seed);
    checkSame(a.camera.target, b.camera.target);
    CHECK(a.camera.distance == b.camera.distance);
    CHECK(a.camera.yawDegrees == b.camera.yawDegrees);
    CHECK(a.camera.pitchDegrees == b.camera.pitchDegrees);
    REQUIRE(a.materials.size() == b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        const EditorMaterial& x = a.materials[i];
        const EditorMaterial& y = b.materials[i];
        CHECK(x.name == y.name);
        checkSame(x.diffuse, y.diffuse);
        checkSame(x.specular, y.specular);
        CHECK(x.shininess == y.shininess);
        CHECK(x.diffuseMap == y.diffuseMap);
        CHECK(x.normalMap == y.normalMap);
        CHECK(x.shader == y.shader);
    }
    REQUIRE(a.objects.size() == b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const EditorObject& x = a.objects[i];
        const EditorObject& y = b.objects[i];
        CHECK(x.id == y.id);
        CHECK(x.name == y.name);
        CHECK(x.mesh == y.mesh);
        CHECK(x.material == y.material);
        checkSame(x.position, y.position);
        checkSame(x.rotationDegrees, y.rotationDegrees);
        checkSame(x.scale, y.scale);
    }
    REQUIRE(a.lights.size() == b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        const EditorLight& x = a.lights[i];
        const EditorLight& y = b.lights[i];
        CHECK(x.id == y.id);
        CHECK(x.name == y.name);
        checkSame(x.position, y.position);
        checkSame(x.color, y.color);
        CHECK(x.radius == y.radius);
        CHECK(x.on == y.on);
    }
}

} // namespace

TEST_CASE("A scene survives a save and a load, every field", "[editor][scene-file]") {
    const EditorScene scene = fullScene();
    const EditorScene loaded = editorSceneFromJson(editorSceneToJson(scene), "scene.json");
    checkSameScene(loaded, scene);
}

TEST_CASE("Save, load, save gives the same bytes, awkward floats included", "[editor][scene-file]") {
    EditorScene scene = fullScene();
    scene.objects[0].position = {0.1f, 1.0f / 3.0f, -0.0f};
    scene.objects[0].scale = {std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max(), 1e-7f};
    scene.objects[1].position = {16777217.0f, 123456790000.0f, 1e20f};
    scene.objects[1].rotationDegrees = {0.1f + 0.2f, 359.99997f, -1e-30f};
    scene.camera.distance = std::nextafter(12.0f, 13.0f);
    const std::string first = editorSceneToJson(scene);
    const EditorScene loaded = editorSceneFromJson(first, "scene.json");
    CHECK(editorSceneToJson(loaded) == first);
    // The floats themselves came back, not just their text (-0 is saved as 0).
    CHECK(loaded.objects[0].scale.x == std::numeric_limits<float>::denorm_min());
    CHECK(loaded.objects[0].scale.y == std::numeric_limits<float>::max());
    CHECK(loaded.objects[1].rotationDegrees.x == 0.1f + 0.2f);
    CHECK(loaded.camera.distance == std::nextafter(12.0f, 13.0f));
    CHECK(loaded.objects[0].position.z == 0.0f);
    CHECK_FALSE(contains(first, "-0,"));
    checkSame(loaded.objects[1].position, scene.objects[1].position);
}

TEST_CASE("A saved scene reads the way the format page shows it", "[editor][scene-file]") {
    EditorScene scene;
    scene.materials.push_back(EditorMaterial{});
    scene.materials[0].name = "stone";
    EditorObject& floor = scene.addObject("floor", "shape:plane", "stone");
    floor.scale = {20.0f, 1.0f, 20.0f};
    const std::string expected = R"({
  "stoa_scene": 2,
  "ambient": [0.1, 0.1, 0.1],
  "sun": {
    "direction": [-0.4, -1, -0.3],
    "color": [1, 1, 1]
  },
  "camera": {
    "target": [0, 0, 0],
    "distance": 12,
    "yaw": 30,
    "pitch": 25
  },
  "renderer": {
    "deferred": false,
    "shadows": true,
    "pcf": 3,
    "normal_maps": true,
    "ssao": false,
    "sky": true,
    "culling": true,
    "debug_view": "final"
  },
  "crowd_world": "",
  "materials": [
    {
      "name": "stone",
      "diffuse": [0.8, 0.8, 0.8],
      "specular": [0.2, 0.2, 0.2],
      "shininess": 32,
      "diffuse_map": "",
      "normal_map": "",
      "shader": ""
    }
  ],
  "objects": [
    {
      "id": 1,
      "name": "floor",
      "mesh": "shape:plane",
      "material": "stone",
      "position": [0, 0, 0],
      "rotation": [0, 0, 0],
      "scale": [20, 1, 20]
    }
  ],
  "lights": []
}
)";
    CHECK(editorSceneToJson(scene) == expected);
}

TEST_CASE("Keys a file leaves out take the defaults of EditorScene.hpp", "[editor][scene-file]") {
    const EditorScene empty = editorSceneFromJson("{\"stoa_scene\": 1}", "scene.json");
    checkSameScene(empty, EditorScene{});
    const EditorScene scene = editorSceneFromJson(kScene, "scene.json");
    REQUIRE(scene.materials.size() == 2);
    CHECK(scene.materials[1].name == "slate");
    CHECK(scene.materials[1].shininess == 8.0f);
    checkSame(scene.materials[1].diffuse, EditorMaterial{}.diffuse);
    CHECK(scene.materials[1].diffuseMap.empty());
    REQUIRE(scene.objects.size() == 2);
    checkSame(scene.objects[1].position, {2.0f, 1.5f, -1.0f});
    checkSame(scene.objects[1].scale, glm::vec3(1.0f));
    checkSame(scene.objects[1].rotationDegrees, glm::vec3(0.0f));
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0].id == 3);
    CHECK(scene.nextId() == 4);
}

TEST_CASE("A version-1 file as this build's first format wrote it still loads", "[editor][scene-file]") {
    // tests/data/editor/scene-version1.json is frozen: never rewrite it with a newer format.
    const EditorScene scene = loadEditorScene(fs::path(STOA_TEST_DATA_DIR) / "editor" / "scene-version1.json");
    checkSame(scene.ambient, {0.1f, 0.12f, 0.15f});
    checkSame(scene.sunDirection, {-0.5f, -1.0f, -0.25f});
    CHECK(scene.camera.distance == 9.5f);
    CHECK(scene.camera.yawDegrees == -40.0f);
    CHECK(scene.renderer.deferred);
    CHECK_FALSE(scene.renderer.shadows);
    CHECK(scene.renderer.pcfSize == 3);   // version 1's 5 texels wide: lab 05's widest, 3 x 3
    CHECK(scene.renderer.ssao);
    CHECK(scene.renderer.debugView == "normals");
    CHECK(scene.crowdWorld == "crowds/explorers.xml");
    REQUIRE(scene.materials.size() == 2);
    CHECK(scene.materials[1].normalMap == "textures/wall_normal.png");
    CHECK(scene.materials[1].shader == "editor/lit");
    REQUIRE(scene.objects.size() == 2);
    CHECK(scene.objects[1].id == 4);
    CHECK(scene.objects[1].mesh == "acropolis/wall.obj");
    checkSame(scene.objects[1].rotationDegrees, {0.0f, 90.0f, 0.0f});
    REQUIRE(scene.lights.size() == 1);
    CHECK_FALSE(scene.lights[0].on);
    CHECK(scene.lights[0].radius == 7.0f);
    CHECK(scene.nextId() == 5);
}

TEST_CASE("The example scene loads, names existing assets and is saved byte for byte", "[editor][scene-file]") {
    const fs::path path = paths::assetsDir() / "scenes" / "example.json";
    const EditorScene scene = loadEditorScene(path);
    CHECK(scene.materials.size() >= 2);
    CHECK(scene.objects.size() >= 3);
    CHECK(scene.lights.size() == 2);
    bool hasFloor = false;
    for (const EditorObject& object : scene.objects) hasFloor = hasFloor || object.mesh == "shape:plane";
    CHECK(hasFloor);
}

TEST_CASE("The scenes in assets/scenes name existing assets and are saved byte for byte", "[editor][scene-file]") {
    for (const char* name : {"example.json", "showcase.json"}) {
        INFO(name);
        const fs::path path = paths::assetsDir() / "scenes" / name;
        const EditorScene scene = loadEditorScene(path);
        for (const EditorMaterial& material : scene.materials) {
            if (!material.diffuseMap.empty()) CHECK(fs::is_regular_file(paths::assetsDir() / material.diffuseMap));
            if (!material.normalMap.empty()) CHECK(fs::is_regular_file(paths::assetsDir() / material.normalMap));
        }
        for (const EditorObject& object : scene.objects)
            if (object.mesh.rfind("shape:", 0) != 0) CHECK(fs::is_regular_file(paths::assetsDir() / object.mesh));
        for (const std::string& mesh : scene.field.meshes)
            if (mesh.rfind("shape:", 0) != 0) CHECK(fs::is_regular_file(paths::assetsDir() / mesh));
        if (!scene.crowdWorld.empty()) CHECK(fs::is_regular_file(paths::assetsDir() / "crowds" / scene.crowdWorld));
        // Written in the saver's own layout, so the editor's first save changes nothing.
        CHECK(editorSceneToJson(scene) == readText(path));
    }
}

TEST_CASE("The showcase has every lab on", "[editor][scene-file]") {
    const EditorScene scene = loadEditorScene(paths::assetsDir() / "scenes" / "showcase.json");
    const EditorRendererSettings& renderer = scene.renderer;
    CHECK((renderer.deferred && renderer.shadows && renderer.normalMaps && renderer.ssao && renderer.sky && renderer.culling));
    CHECK(renderer.debugView == "final");
    CHECK(scene.field.rows * scene.field.rows >= 300);   // a wide field for culling and LOD
    CHECK(scene.lightSwarm.count >= 200);                // hundreds of point lights
    CHECK_FALSE(scene.crowdWorld.empty());
    int normalMapped = 0;
    for (const EditorObject& object : scene.objects)
        if (const EditorMaterial* material = scene.findMaterial(object.material); material && !material->normalMap.empty())
            ++normalMapped;
    CHECK(normalMapped >= 3);   // the floor, the wall, the statue
}

TEST_CASE("saveEditorScene replaces the file in one step and never leaves a half-written one", "[editor][scene-file]") {
    TempFolder folder("editor-scene");
    const EditorScene scene = fullScene();

    SECTION("a save, then a save over it") {
        const fs::path file = folder / "level.json";
        saveEditorScene(EditorScene{}, file);
        saveEditorScene(scene, file);
        CHECK(readText(file) == editorSceneToJson(scene));
        checkSameScene(loadEditorScene(file), scene);
        // Only the scene file is left: no temporary beside it.
        CHECK(std::distance(fs::directory_iterator(folder.path()), fs::directory_iterator()) == 1);
    }
    SECTION("a folder that does not exist: an error naming the file, and nothing written") {
        const fs::path file = folder / "missing" / "level.json";
        try {
            saveEditorScene(scene, file);
            FAIL("saved into a folder that does not exist");
        } catch (const InputError& error) {
            CHECK(error.file() == file.string());
            CHECK(contains(error.message(), "does not exist"));
        }
        CHECK_FALSE(fs::exists(folder / "missing"));
        CHECK(fs::is_empty(folder.path()));
    }
    SECTION("a number a file cannot hold: the old file stays as it was") {
        const fs::path file = folder.write("level.json", "the old scene\n");
        EditorScene broken = scene;
        broken.lights[0].radius = std::numeric_limits<float>::quiet_NaN();
        try {
            saveEditorScene(broken, file);
            FAIL("saved a NaN");
        } catch (const InputError& error) {
            CHECK(error.file() == file.string());
            CHECK(contains(error.message(), "lights[0].radius"));
        }
        CHECK(readText(file) == "the old scene\n");
        CHECK(std::distance(fs::directory_iterator(folder.path()), fs::directory_iterator()) == 1);
    }
    SECTION("a folder in the file's place: refused, the folder untouched, no temporary left") {
        fs::create_directories(folder / "level.json" / "inside");
        CHECK_THROWS_AS(saveEditorScene(scene, folder / "level.json"), InputError);
        CHECK(fs::is_directory(folder / "level.json" / "inside"));
        CHECK(std::distance(fs::directory_iterator(folder.path()), fs::directory_iterator()) == 1);
    }
}

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
    checkRefused(huge, lineOf(huge, "1e39"), "camera.yaw: 1e39 is out of range for a float");
}

TEST_CASE("Ids, materials and ranges are checked", "[editor][scene-file]") {
    const std::string twice = replaced(kScene, "\"id\": 3", "\"id\": 2");
    checkRefused(twice, lineOf(twice, "\"id\": 2,\n      \"name\": \"lamp\""),
                 "lights[0].id: id 2 is used twice, by objects[1] (\"column\", line " +
                     std::to_string(lineOf(twice, "\"id\": 2")) + ") and by lights[0] (\"lamp\")");
    const std::string zero = replaced(kScene, "\"id\": 1,", "\"id\": 0,");
    checkRefused(zero, lineOf(zero, "\"id\": 0"), "objects[0].id: ids start at 1; 0 is not an id");
    const std::string negative = replaced(kScene, "\"id\": 1,", "\"id\": -4,");
    checkRefused(negative, lineOf(negative, "\"id\": -4"), "an id is a whole number from 1 to 4294967295");
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
    checkRefused(rows, lineOf(rows, "\"rows\": 0"), "field.rows: expected a whole number from 1 to 100 (copies per side), found the number 0");
    const std::string material = replaced(v2, "\"material\": \"marble\", \"rows\"", "\"material\": \"gold\", \"rows\"");
    checkRefused(material, lineOf(material, "gold"), "field.material: no material is called \"gold\"");
    const std::string meshes = replaced(v2, "[\"shape:cube\"]", "\"shape:cube\"");
    checkRefused(meshes, lineOf(meshes, "\"meshes\""), "field.meshes: expected an array of asset names");
    const std::string count = replaced(v2, "\"count\": 10", "\"count\": 5000");
    checkRefused(count, lineOf(count, "5000"), "light_swarm.count: expected a whole number from 0 to 4096");
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
