// The editor's scene files (EditorSceneFile.hpp, docs/scene-files.md), saved
// and loaded: every field survives a save and a load, a second save gives the
// same bytes, a frozen version-1 file and the example scenes load, every scene
// the editor saves after random edits loads again (ids included), and saving
// never leaves a half-written file. EditorSceneFileTests.cpp checks that each
// mistake in a file is refused; EditorSceneSafeSaveTests.cpp what a save must
// not replace.

#include "catch.hpp"
#include "EditorSceneFileSamples.hpp"
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
#include <random>
#include <string>
#include <vector>

using namespace stoa;
using stoa::test::TempFolder;
namespace fs = std::filesystem;

namespace {

using stoa::test::scene_file::contains;
using stoa::test::scene_file::kScene;
using stoa::test::scene_file::readText;


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

/// Random edits the way the editor makes them (EditorLabApp's spawn, delete and
/// move), with undo and redo. Undo here restores a whole copy of the scene as it
/// was: lab 11's EditHistory, which undoes with commands, is the student's and out
/// of the framework's reach, and a test that shipped a second one would hand it out.
class RandomEdits {
public:
    explicit RandomEdits(unsigned seed) : m_random(seed) {}

    void edit(EditorScene& scene) {
        if (m_states.empty()) m_states.push_back(scene);
        switch (pick(6)) {
        case 0:
        case 1: spawn(scene); break;
        case 2: remove(scene); break;
        case 3: move(scene); break;
        case 4: step(scene, -1); break;
        default: step(scene, +1); break;
        }
    }

    /// A reopened file starts with no history, as in the editor.
    void forget() {
        m_states.clear();
        m_current = 0;
    }

private:
    std::size_t pick(std::size_t count) { return std::uniform_int_distribution<std::size_t>(0, count - 1)(m_random); }
    float coordinate() { return std::uniform_real_distribution<float>(-50.0f, 50.0f)(m_random); }

    // After an edit the scene is a new state; the states after the current one are gone.
    void changed(const EditorScene& scene) {
        m_states.resize(m_current + 1);
        m_states.push_back(scene);
        ++m_current;
    }

    // Undo (-1) or redo (+1): the state before or after the current one, when there is one.
    void step(EditorScene& scene, int direction) {
        if (direction < 0 && m_current == 0) return;
        if (direction > 0 && m_current + 1 >= m_states.size()) return;
        m_current = direction < 0 ? m_current - 1 : m_current + 1;
        scene = m_states[m_current];
    }

    void spawn(EditorScene& scene) {
        if (scene.materials.empty()) return;
        static const char* const shapes[] = {"shape:cube", "shape:sphere", "shape:cylinder", "shape:plane"};
        EditorObject object;
        object.id = scene.nextId();
        object.name = "spawned " + std::to_string(object.id);
        object.mesh = shapes[pick(4)];
        object.material = scene.materials.front().name;
        object.position = {coordinate(), coordinate(), coordinate()};
        scene.objects.push_back(object);
        changed(scene);
    }

    void remove(EditorScene& scene) {
        if (scene.objects.empty()) return;
        scene.removeObject(scene.objects[pick(scene.objects.size())].id);
        changed(scene);
    }

    void move(EditorScene& scene) {
        if (scene.objects.empty()) return;
        scene.objects[pick(scene.objects.size())].position = {coordinate(), coordinate(), coordinate()};
        changed(scene);
    }

    std::mt19937 m_random;
    std::vector<EditorScene> m_states;   // every state since the file was opened, in order
    std::size_t m_current = 0;           // the one the scene is in
};

/// Opens `file`, then again and again: random edits, save, open; each saved
/// file must open as the scene that was saved.
void checkEditsRoundTrip(const fs::path& file, const TempFolder& folder) {
    for (unsigned seed = 1; seed <= 8; ++seed) {
        INFO("seed " << seed);
        const fs::path saved = folder / ("saved-" + std::to_string(seed) + ".json");
        EditorScene scene = loadEditorScene(file);
        RandomEdits edits(seed);
        for (int round = 0; round < 6; ++round) {
            for (int i = 0; i < 25; ++i) edits.edit(scene);
            saveEditorScene(scene, saved);
            const EditorScene loaded = loadEditorScene(saved);
            checkSameScene(loaded, scene);
            scene = loaded;
            edits.forget();
        }
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

TEST_CASE("Every scene the editor saves after random edits opens again", "[editor][scene-file]") {
    TempFolder folder("editor-scene");
    std::vector<fs::path> files = {fs::path(STOA_TEST_DATA_DIR) / "editor" / "scene-version1.json"};
    for (const fs::directory_entry& entry : fs::directory_iterator(paths::assetsDir() / "scenes"))
        if (entry.path().extension() == ".json") files.push_back(entry.path());
    REQUIRE(files.size() >= 3);
    // The largest id the reader accepts, on a light (never deleted) and on an
    // object (deleted, undone, redone): the next spawn takes the smallest free id.
    const auto withLargestId = [](const std::string& id) {
        const std::string from = "\"id\": " + id + ",";
        return std::string(kScene).replace(kScene.find(from), from.size(), "\"id\": 16777215,");
    };
    files.push_back(folder.write("largest-light.json", withLargestId("3")));
    files.push_back(folder.write("largest-object.json", withLargestId("2")));
    REQUIRE(loadEditorScene(files.back()).objects[1].id == EditorScene::kMaxId);
    for (const fs::path& file : files) {
        INFO(file.string());
        checkEditsRoundTrip(file, folder);
    }
}

TEST_CASE("nextId never wraps: past EditorScene::kMaxId it gives the smallest free id", "[editor][scene-file]") {
    EditorScene scene;
    CHECK(scene.nextId() == 1);
    scene.addObject("last", "shape:cube", "").id = EditorScene::kMaxId;
    CHECK(scene.nextId() == 1);
    CHECK(scene.addObject("first", "shape:cube", "").id == 1);
    EditorLight lamp;
    lamp.id = 2;
    scene.lights.push_back(lamp);
    CHECK(scene.nextId() == 3);
    scene.objects[0].id = 0xFFFFFFFFu;   // set by code, not by a file: still no wrap to 0
    CHECK(scene.nextId() == 3);
    scene.objects[0].id = 7;
    CHECK(scene.nextId() == 8);
}

TEST_CASE("A scene whose ids a file cannot hold is not saved", "[editor][scene-file]") {
    TempFolder folder("editor-scene");
    const fs::path file = folder.write("level.json", "the old scene\n");
    const auto refused = [&](const EditorScene& scene, const std::string& part) {
        try {
            saveEditorScene(scene, file);
            FAIL("saved ids no file accepts");
        } catch (const InputError& error) {
            INFO(error.what());
            CHECK(error.file() == file.string());
            CHECK(contains(error.message(), part));
        }
        CHECK(readText(file) == "the old scene\n");
    };
    EditorScene scene = fullScene();
    scene.objects[1].id = 0;
    refused(scene, "objects[1].id is 0, but an id is a whole number from 1 to 16777215");
    scene.objects[1].id = EditorScene::kMaxId + 1;
    refused(scene, "objects[1].id is 16777216");
    scene.objects[1].id = scene.lights[0].id;
    refused(scene, "lights[0].id 9 is also the id of objects[1]");
}
