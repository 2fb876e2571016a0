#include <stoa/editor/EditorSceneFile.hpp>

#include "JsonDocument.hpp"
#include "SafeSave.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <stdexcept>

namespace stoa {

namespace fs = std::filesystem;
using json::Member;
using json::Value;

namespace {

const char* const kShapes[] = {"shape:cube", "shape:sphere", "shape:cylinder", "shape:plane"};

std::string joined(std::initializer_list<const char*> names) {
    std::string text;
    for (const char* name : names) text += (text.empty() ? "" : ", ") + std::string(name);
    return text;
}

std::string numberText(float value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

/// Reads one scene file's tree into an EditorScene. Each check throws
/// InputError(file, line of the offending value, "where: what was expected").
/// `where` names a value the way a reader finds it: "sun.color",
/// "objects[2].position".
class SceneReader {
public:
    explicit SceneReader(const std::string& file) : m_file(file) {}

    EditorScene read(const Value& root) {
        if (root.kind != Value::Kind::Object) {
            fail(root.line, "not a Stoa scene file: it holds " + json::describe(root) +
                                ", not an object starting with \"stoa_scene\"");
        }
        readVersion(root);
        EditorScene scene;
        const std::initializer_list<const char*> keys = {"stoa_scene", "ambient", "sun", "camera", "renderer",
                                                          "crowd_world", "field", "light_swarm", "materials", "objects", "lights"};
        checkKeys(root, "the scene", keys);
        // Materials before objects, whatever the order in the file: an object names one.
        if (const Value* value = find(root, "ambient")) scene.ambient = color(*value, "ambient");
        if (const Value* value = find(root, "sun")) readSun(*value, scene);
        if (const Value* value = find(root, "camera")) readCamera(*value, scene.camera);
        if (const Value* value = find(root, "renderer")) readRenderer(*value, scene.renderer);
        if (const Value* value = find(root, "crowd_world")) scene.crowdWorld = string(*value, "crowd_world");
        if (const Value* value = find(root, "materials")) {
            forEachItem(*value, "materials", [&](const Value& item, const std::string& where) {
                scene.materials.push_back(readMaterial(item, where, scene));
            });
        }
        newInVersion2(root, "field", "field");
        newInVersion2(root, "light_swarm", "light_swarm");
        if (const Value* value = find(root, "field")) readField(*value, scene.field);
        if (const Value* value = find(root, "light_swarm")) readLightSwarm(*value, scene.lightSwarm);
        if (const Value* value = find(root, "objects")) {
            forEachItem(*value, "objects", [&](const Value& item, const std::string& where) {
                scene.objects.push_back(readObject(item, where, scene));
            });
        }
        if (const Value* value = find(root, "lights")) {
            forEachItem(*value, "lights", [&](const Value& item, const std::string& where) {
                scene.lights.push_back(readLight(item, where));
            });
        }
        return scene;
    }

private:
    struct IdUse {
        std::string where;
        std::string name;
        int line;
    };

    [[noreturn]] void fail(int line, const std::string& message) const { throw InputError(m_file, line, message); }

    void readVersion(const Value& root) {
        const Value* version = find(root, "stoa_scene");
        if (!version) fail(root.line, "not a Stoa scene file: no \"stoa_scene\" version");
        if (version->kind != Value::Kind::Number || !version->whole || !version->fitsInteger || version->integer < 1) {
            fail(version->line, "\"stoa_scene\" is the format's version, a whole number from 1; found " +
                                    json::describe(*version));
        }
        if (version->integer > EditorScene::kFormatVersion) {
            fail(version->line, "written by a newer Stoa: version " + std::to_string(version->integer) +
                                    ", this build reads " + std::to_string(EditorScene::kFormatVersion) +
                                    " (open it with a newer Stoa)");
        }
        // What a version lacks keeps its default; what changed meaning is
        // carried over where it is read (renderer.pcf).
        m_version = static_cast<int>(version->integer);
    }

    static const Value* find(const Value& object, const char* key) {
        for (const Member& member : object.members)
            if (member.key == key) return &member.value;
        return nullptr;
    }

    void checkKeys(const Value& object, const std::string& where, std::initializer_list<const char*> allowed) const {
        for (const Member& member : object.members) {
            bool known = false;
            for (const char* key : allowed) known = known || member.key == key;
            if (!known) {
                fail(member.line, "unknown key \"" + quoteInput(member.key) + "\" in " + where +
                                      "; the keys allowed there are: " + joined(allowed));
            }
        }
    }

    /// `value` as an object whose keys are all in `allowed`.
    void object(const Value& value, const std::string& where, std::initializer_list<const char*> allowed) const {
        if (value.kind != Value::Kind::Object) fail(value.line, where + ": expected an object { ... }, found " + json::describe(value));
        checkKeys(value, where, allowed);
    }

    template <typename Read>
    void forEachItem(const Value& value, const std::string& where, Read read) const {
        if (value.kind != Value::Kind::Array)
            fail(value.line, where + ": expected an array of objects [{ ... }, ...], found " + json::describe(value));
        for (std::size_t i = 0; i < value.items.size(); ++i) read(value.items[i], where + "[" + std::to_string(i) + "]");
    }

    float number(const Value& value, const std::string& where) const {
        if (value.kind != Value::Kind::Number) fail(value.line, where + ": expected a number, found " + json::describe(value));
        if (value.outOfRange) fail(value.line, where + ": " + quoteInput(value.text, 24) + " is too large for a float (about 3.4e38 at most)");
        return value.number;
    }

    float positive(const Value& value, const std::string& where, const char* meaning) const {
        const float result = number(value, where);
        // A non-zero number a float holds as 0 (1e-60): say so, rather than "found 1e-60".
        const std::string mantissa = value.text.substr(0, value.text.find_first_of("eE"));
        if (result == 0.0f && mantissa.find_first_of("123456789") != std::string::npos)
            fail(value.line, where + ": " + quoteInput(value.text, 24) + " is too close to 0 for a float, which holds it as 0; "
                                     "it must be greater than 0 (" + meaning + ")");
        if (!(result > 0.0f)) fail(value.line, where + ": must be greater than 0 (" + meaning + "), found " + value.text);
        return result;
    }

    glm::vec3 vec3(const Value& value, const std::string& where) const {
        const auto wrong = [&](const Value& at, const std::string& found) {
            fail(at.line, where + ": expected an array of 3 numbers [x, y, z], found " + found);
        };
        if (value.kind != Value::Kind::Array) wrong(value, json::describe(value));
        if (value.items.size() != 3) wrong(value, json::describe(value));
        glm::vec3 result;
        for (int i = 0; i < 3; ++i) {
            const Value& item = value.items[i];
            if (item.kind != Value::Kind::Number) wrong(item, "an array holding " + json::describe(item));
            result[i] = number(item, where + "[" + std::to_string(i) + "]");
        }
        return result;
    }

    /// Linear RGB, each component at least 0 (and at most 1 when `atMostOne`).
    glm::vec3 color(const Value& value, const std::string& where, bool atMostOne = false) const {
        const glm::vec3 rgb = vec3(value, where);
        for (int i = 0; i < 3; ++i) {
            if (rgb[i] < 0.0f || (atMostOne && rgb[i] > 1.0f)) {
                fail(value.items[i].line, where + ": a colour's components are " + (atMostOne ? "from 0 to 1" : "0 or more") +
                                              " (linear RGB), found " + value.items[i].text);
            }
        }
        return rgb;
    }

    bool boolean(const Value& value, const std::string& where) const {
        if (value.kind != Value::Kind::Boolean) fail(value.line, where + ": expected true or false, found " + json::describe(value));
        return value.boolean;
    }

    std::string string(const Value& value, const std::string& where) const {
        if (value.kind != Value::Kind::String) fail(value.line, where + ": expected a string \"...\", found " + json::describe(value));
        for (const char c : value.text) {
            if (static_cast<unsigned char>(c) < 0x20) {
                fail(value.line, where + ": a control character (such as a line break or \\u0000) has no place in a "
                                         "name or an asset name");
            }
        }
        return value.text;
    }

    std::uint32_t id(const Value& value, const std::string& where, const std::string& name) {
        if (value.kind != Value::Kind::Number || !value.whole)
            fail(value.line, where + ": expected a whole number from 1 to " + std::to_string(EditorScene::kMaxId) +
                                 ", found " + json::describe(value));
        if (value.fitsInteger && value.integer == 0) fail(value.line, where + ": ids start at 1; 0 is not an id");
        // Past kMaxId the editor could not number the next object after it.
        if (!value.fitsInteger || value.integer < 0 || value.integer > EditorScene::kMaxId) {
            fail(value.line, where + ": id " + quoteInput(value.text, 24) +
                                 " is out of range: an id is a whole number from 1 to " +
                                 std::to_string(EditorScene::kMaxId));
        }
        const auto id = static_cast<std::uint32_t>(value.integer);
        const std::string owner = where.substr(0, where.rfind('.'));
        const auto [first, inserted] = m_ids.emplace(id, IdUse{owner, name, value.line});
        if (!inserted) {
            fail(value.line, where + ": id " + value.text + " is used twice, by " + first->second.where + " (\"" +
                                 quoteInput(first->second.name) + "\", line " + std::to_string(first->second.line) +
                                 ") and by " + owner + " (\"" + quoteInput(name) +
                                 "\"); objects and lights share one set of ids");
        }
        return id;
    }

    /// A mesh name starting with "shape:" must name one of the shapes.
    void checkShape(const std::string& mesh, int line, const std::string& where) const {
        if (mesh.compare(0, 6, "shape:") != 0) return;
        bool known = false;
        for (const char* shape : kShapes) known = known || mesh == shape;
        if (!known) {
            fail(line, where + ": unknown shape \"" + quoteInput(mesh) +
                           "\"; the shapes are shape:cube, shape:sphere, shape:cylinder, shape:plane");
        }
    }

    /// A key version 1 did not have, in a file that says it is version 1.
    void newInVersion2(const Value& object, const char* key, const std::string& where) const {
        if (m_version >= 2) return;
        for (const Member& member : object.members)
            if (member.key == key)
                fail(member.value.line, where + ": new in version 2 of the format, but the file says \"stoa_scene\": 1 "
                                              "(write 2, or leave the key out)");
    }

    int wholeInRange(const Value& value, const std::string& where, long long low, long long high, const char* meaning) const {
        if (value.kind != Value::Kind::Number || !value.whole || !value.fitsInteger || value.integer < low ||
            value.integer > high) {
            fail(value.line, where + ": expected a whole number from " + std::to_string(low) + " to " +
                                 std::to_string(high) + " (" + meaning + "), found " + json::describe(value));
        }
        return static_cast<int>(value.integer);
    }

    void readField(const Value& value, EditorField& field) const {
        object(value, "field", {"meshes", "material", "rows", "spacing", "clear_radius", "seed"});
        if (const Value* meshes = find(value, "meshes")) {
            if (meshes->kind != Value::Kind::Array)
                fail(meshes->line, "field.meshes: expected an array of asset names [\"...\", ...], found " + json::describe(*meshes));
            for (std::size_t i = 0; i < meshes->items.size(); ++i) {
                const std::string where = "field.meshes[" + std::to_string(i) + "]";
                field.meshes.push_back(string(meshes->items[i], where));
                const std::string& mesh = field.meshes.back();
                if (mesh.empty()) fail(meshes->items[i].line, where + ": must not be empty");
                checkShape(mesh, meshes->items[i].line, where);
            }
        }
        if (const Value* material = find(value, "material")) {
            field.material = string(*material, "field.material");
            if (!field.material.empty() && m_materials.count(field.material) == 0)
                fail(material->line, "field.material: no material is called \"" + quoteInput(field.material) + "\"");
        }
        if (const Value* rows = find(value, "rows"))
            field.rows = wholeInRange(*rows, "field.rows", 1, EditorField::kMaxRows,
                                      "copies per side; 100 x 100 draw in 1.8 times the showcase's frame on a 2-core "
                                      "machine with llvmpipe");
        if (const Value* spacing = find(value, "spacing"))
            field.spacing = positive(*spacing, "field.spacing", "metres between neighbouring places");
        if (const Value* clear = find(value, "clear_radius")) {
            field.clearRadius = number(*clear, "field.clear_radius");
            if (field.clearRadius < 0.0f) fail(clear->line, "field.clear_radius: must be 0 or more, found " + clear->text);
        }
        if (const Value* seed = find(value, "seed")) field.seed = wholeInRange(*seed, "field.seed", 0, 2147483647, "any");
    }

    void readLightSwarm(const Value& value, EditorLightSwarm& swarm) const {
        object(value, "light_swarm", {"count", "radius", "height", "brightness", "seed"});
        if (const Value* count = find(value, "count"))
            swarm.count = wholeInRange(*count, "light_swarm.count", 0, EditorLightSwarm::kMaxCount,
                                       "how many lights; 2000 draw in 1.9 times the showcase's frame on a 2-core "
                                       "machine with llvmpipe");
        if (const Value* radius = find(value, "radius"))
            swarm.radius = positive(*radius, "light_swarm.radius", "how far from the origin they wander");
        if (const Value* height = find(value, "height")) {
            swarm.height = number(*height, "light_swarm.height");
            if (!(swarm.height >= 0.3f)) fail(height->line, "light_swarm.height: must be 0.3 or more (metres; the paths start 0.3 m up), found " + height->text);
        }
        if (const Value* brightness = find(value, "brightness"))
            swarm.brightness = positive(*brightness, "light_swarm.brightness", "scales every light's colour");
        if (const Value* seed = find(value, "seed")) swarm.seed = wholeInRange(*seed, "light_swarm.seed", 0, 2147483647, "any");
    }

    void readSun(const Value& value, EditorScene& scene) const {
        object(value, "sun", {"direction", "color"});
        if (const Value* direction = find(value, "direction")) {
            scene.sunDirection = vec3(*direction, "sun.direction");
            if (scene.sunDirection == glm::vec3(0.0f)) fail(direction->line, "sun.direction: must not be [0, 0, 0] (the way the sunlight travels)");
        }
        if (const Value* sunColor = find(value, "color")) scene.sunColor = color(*sunColor, "sun.color");
    }

    void readCamera(const Value& value, EditorCamera& camera) const {
        object(value, "camera", {"target", "distance", "yaw", "pitch"});
        if (const Value* target = find(value, "target")) camera.target = vec3(*target, "camera.target");
        if (const Value* distance = find(value, "distance"))
            camera.distance = positive(*distance, "camera.distance", "from the target to the eye");
        if (const Value* yaw = find(value, "yaw")) camera.yawDegrees = number(*yaw, "camera.yaw");
        if (const Value* pitch = find(value, "pitch")) camera.pitchDegrees = number(*pitch, "camera.pitch");
    }

    void readRenderer(const Value& value, EditorRendererSettings& renderer) const {
        object(value, "renderer", {"deferred", "shadows", "pcf", "normal_maps", "ssao", "sky", "culling", "debug_view"});
        if (const Value* on = find(value, "deferred")) renderer.deferred = boolean(*on, "renderer.deferred");
        if (const Value* on = find(value, "shadows")) renderer.shadows = boolean(*on, "renderer.shadows");
        if (const Value* pcf = find(value, "pcf")) {
            if (m_version == 1) {
                // Version 1 gave the filter's width, 1, 3 or 5 texels; lab 05's widest is 3 x 3.
                if (pcf->kind != Value::Kind::Number || !pcf->whole || !pcf->fitsInteger ||
                    (pcf->integer != 1 && pcf->integer != 3 && pcf->integer != 5)) {
                    fail(pcf->line, "renderer.pcf: expected 1, 3 or 5 (the shadow filter's width in texels), found " +
                                        json::describe(*pcf));
                }
                renderer.pcfSize = pcf->integer == 1 ? 1 : 3;
            } else {
                renderer.pcfSize = wholeInRange(*pcf, "renderer.pcf", 1, 3,
                                                "lab 05's shadow filter: 1 one tap, 2 the 2x2, 3 the 3x3 texels");
            }
        }
        if (const Value* on = find(value, "normal_maps")) renderer.normalMaps = boolean(*on, "renderer.normal_maps");
        if (const Value* on = find(value, "ssao")) renderer.ssao = boolean(*on, "renderer.ssao");
        newInVersion2(value, "sky", "renderer.sky");
        newInVersion2(value, "culling", "renderer.culling");
        if (const Value* on = find(value, "sky")) renderer.sky = boolean(*on, "renderer.sky");
        if (const Value* on = find(value, "culling")) renderer.culling = boolean(*on, "renderer.culling");
        if (const Value* view = find(value, "debug_view")) {
            renderer.debugView = string(*view, "renderer.debug_view");
            if (renderer.debugView.empty()) fail(view->line, "renderer.debug_view: must not be empty (\"final\" draws the finished picture)");
        }
    }

    EditorMaterial readMaterial(const Value& value, const std::string& where, const EditorScene& scene) {
        object(value, where, {"name", "diffuse", "specular", "shininess", "diffuse_map", "normal_map", "shader"});
        EditorMaterial material;
        const Value* name = find(value, "name");
        if (!name) fail(value.line, where + ": no \"name\" (objects name their material)");
        material.name = string(*name, where + ".name");
        if (material.name.empty()) fail(name->line, where + ".name: must not be empty");
        const auto [first, inserted] = m_materials.emplace(material.name, scene.materials.size());
        if (!inserted) {
            fail(name->line, where + ".name: \"" + quoteInput(material.name) + "\" is already the name of materials[" +
                                 std::to_string(first->second) + "]; each material needs its own");
        }
        if (const Value* diffuse = find(value, "diffuse")) material.diffuse = color(*diffuse, where + ".diffuse", true);
        if (const Value* specular = find(value, "specular")) material.specular = color(*specular, where + ".specular", true);
        if (const Value* shininess = find(value, "shininess"))
            material.shininess = positive(*shininess, where + ".shininess", "the Blinn-Phong exponent");
        if (const Value* map = find(value, "diffuse_map")) material.diffuseMap = string(*map, where + ".diffuse_map");
        if (const Value* map = find(value, "normal_map")) material.normalMap = string(*map, where + ".normal_map");
        if (const Value* shader = find(value, "shader")) material.shader = string(*shader, where + ".shader");
        return material;
    }

    EditorObject readObject(const Value& value, const std::string& where, const EditorScene& scene) {
        object(value, where, {"id", "name", "mesh", "material", "position", "rotation", "scale"});
        EditorObject result;
        if (const Value* name = find(value, "name")) result.name = string(*name, where + ".name");
        const Value* idValue = find(value, "id");
        if (!idValue) fail(value.line, where + ": no \"id\" (a whole number from 1, unique among objects and lights)");
        result.id = id(*idValue, where + ".id", result.name);
        const Value* mesh = find(value, "mesh");
        if (!mesh) fail(value.line, where + ": no \"mesh\" (\"shape:cube\", \"shape:sphere\", \"shape:cylinder\", \"shape:plane\" or an OBJ asset)");
        result.mesh = string(*mesh, where + ".mesh");
        if (result.mesh.empty()) fail(mesh->line, where + ".mesh: must not be empty");
        checkShape(result.mesh, mesh->line, where + ".mesh");
        const Value* material = find(value, "material");
        if (!material) fail(value.line, where + ": no \"material\" (the name of one of the scene's materials)");
        result.material = string(*material, where + ".material");
        if (m_materials.count(result.material) == 0) {
            std::string names;
            const std::size_t listed = std::min<std::size_t>(scene.materials.size(), 12);
            for (std::size_t i = 0; i < listed; ++i) names += (i ? ", " : "") + quoteInput(scene.materials[i].name);
            if (listed < scene.materials.size()) names += ", ... (" + std::to_string(scene.materials.size()) + " in all)";
            fail(material->line, where + ".material: no material is called \"" + quoteInput(result.material) + "\"" +
                                     (names.empty() ? std::string("; the scene has no materials") : "; the materials are: " + names));
        }
        if (const Value* position = find(value, "position")) result.position = vec3(*position, where + ".position");
        if (const Value* rotation = find(value, "rotation")) result.rotationDegrees = vec3(*rotation, where + ".rotation");
        if (const Value* scale = find(value, "scale")) result.scale = vec3(*scale, where + ".scale");
        return result;
    }

    EditorLight readLight(const Value& value, const std::string& where) {
        object(value, where, {"id", "name", "position", "color", "radius", "on"});
        EditorLight light;
        if (const Value* name = find(value, "name")) light.name = string(*name, where + ".name");
        const Value* idValue = find(value, "id");
        if (!idValue) fail(value.line, where + ": no \"id\" (a whole number from 1, unique among objects and lights)");
        light.id = id(*idValue, where + ".id", light.name);
        if (const Value* position = find(value, "position")) light.position = vec3(*position, where + ".position");
        if (const Value* lightColor = find(value, "color")) light.color = color(*lightColor, where + ".color");
        if (const Value* radius = find(value, "radius")) light.radius = positive(*radius, where + ".radius", "where its light ends");
        if (const Value* on = find(value, "on")) light.on = boolean(*on, where + ".on");
        return light;
    }

    const std::string& m_file;
    std::map<std::uint32_t, IdUse> m_ids;               // each id read so far, and who has it
    std::map<std::string, std::size_t> m_materials;     // each material's name and index
    int m_version = EditorScene::kFormatVersion;        // the file's
};

/// Writes the scene's text: each line by hand, so that the layout (one vec3
/// per line, keys in the order of the reference page) never depends on a
/// library's choices.
class SceneWriter {
public:
    std::string write(const EditorScene& scene) {
        m_out = "{\n";
        field(1, "stoa_scene", std::to_string(EditorScene::kFormatVersion));
        field(1, "ambient", vec3(scene.ambient, "ambient"));
        open(1, "sun", '{');
        field(2, "direction", vec3(scene.sunDirection, "sun.direction"));
        field(2, "color", vec3(scene.sunColor, "sun.color"), true);
        close(1, '}');
        open(1, "camera", '{');
        field(2, "target", vec3(scene.camera.target, "camera.target"));
        field(2, "distance", number(scene.camera.distance, "camera.distance"));
        field(2, "yaw", number(scene.camera.yawDegrees, "camera.yaw"));
        field(2, "pitch", number(scene.camera.pitchDegrees, "camera.pitch"), true);
        close(1, '}');
        const EditorRendererSettings& renderer = scene.renderer;
        open(1, "renderer", '{');
        field(2, "deferred", boolean(renderer.deferred));
        field(2, "shadows", boolean(renderer.shadows));
        field(2, "pcf", std::to_string(renderer.pcfSize));
        field(2, "normal_maps", boolean(renderer.normalMaps));
        field(2, "ssao", boolean(renderer.ssao));
        field(2, "sky", boolean(renderer.sky));
        field(2, "culling", boolean(renderer.culling));
        field(2, "debug_view", string(renderer.debugView), true);
        close(1, '}');
        field(1, "crowd_world", string(scene.crowdWorld));
        if (!scene.field.meshes.empty()) {
            const EditorField& f = scene.field;
            open(1, "field", '{');
            std::string meshes = "[";
            for (std::size_t i = 0; i < f.meshes.size(); ++i) meshes += (i ? ", " : "") + string(f.meshes[i]);
            field(2, "meshes", meshes + "]");
            field(2, "material", string(f.material));
            field(2, "rows", std::to_string(f.rows));
            field(2, "spacing", number(f.spacing, "field.spacing"));
            field(2, "clear_radius", number(f.clearRadius, "field.clear_radius"));
            field(2, "seed", std::to_string(f.seed), true);
            close(1, '}');
        }
        if (scene.lightSwarm.count > 0) {
            const EditorLightSwarm& swarm = scene.lightSwarm;
            open(1, "light_swarm", '{');
            field(2, "count", std::to_string(swarm.count));
            field(2, "radius", number(swarm.radius, "light_swarm.radius"));
            field(2, "height", number(swarm.height, "light_swarm.height"));
            field(2, "brightness", number(swarm.brightness, "light_swarm.brightness"));
            field(2, "seed", std::to_string(swarm.seed), true);
            close(1, '}');
        }
        list(scene.materials, "materials", [&](const EditorMaterial& material, const std::string& where) {
            field(3, "name", string(material.name));
            field(3, "diffuse", vec3(material.diffuse, where + ".diffuse"));
            field(3, "specular", vec3(material.specular, where + ".specular"));
            field(3, "shininess", number(material.shininess, where + ".shininess"));
            field(3, "diffuse_map", string(material.diffuseMap));
            field(3, "normal_map", string(material.normalMap));
            field(3, "shader", string(material.shader), true);
        });
        list(scene.objects, "objects", [&](const EditorObject& object, const std::string& where) {
            field(3, "id", std::to_string(object.id));
            field(3, "name", string(object.name));
            field(3, "mesh", string(object.mesh));
            field(3, "material", string(object.material));
            field(3, "position", vec3(object.position, where + ".position"));
            field(3, "rotation", vec3(object.rotationDegrees, where + ".rotation"));
            field(3, "scale", vec3(object.scale, where + ".scale"), true);
        });
        list(scene.lights, "lights", [&](const EditorLight& light, const std::string& where) {
            field(3, "id", std::to_string(light.id));
            field(3, "name", string(light.name));
            field(3, "position", vec3(light.position, where + ".position"));
            field(3, "color", vec3(light.color, where + ".color"));
            field(3, "radius", number(light.radius, where + ".radius"));
            field(3, "on", boolean(light.on), true);
        }, true);
        m_out += "}\n";
        return std::move(m_out);
    }

private:
    void indent(int depth) { m_out.append(static_cast<std::size_t>(2 * depth), ' '); }

    void field(int depth, const char* key, const std::string& value, bool last = false) {
        indent(depth);
        m_out += '"';
        m_out += key;
        m_out += "\": " + value + (last ? "\n" : ",\n");
    }

    void open(int depth, const char* key, char bracket) {
        indent(depth);
        m_out += '"';
        m_out += key;
        m_out += "\": ";
        m_out += bracket;
        m_out += '\n';
    }

    void close(int depth, char bracket, bool last = false) {
        indent(depth);
        m_out += bracket;
        m_out += last ? "\n" : ",\n";
    }

    template <typename Item, typename Write>
    void list(const std::vector<Item>& items, const char* key, Write write, bool last = false) {
        if (items.empty()) {
            field(1, key, "[]", last);
            return;
        }
        open(1, key, '[');
        for (std::size_t i = 0; i < items.size(); ++i) {
            indent(2);
            m_out += "{\n";
            write(items[i], std::string(key) + "[" + std::to_string(i) + "]");
            close(2, '}', i + 1 == items.size());
        }
        close(1, ']', last);
    }

    /// The fewest digits that read back to the same float (std::to_chars'
    /// promise), so save, load, save gives the same bytes; -0 is written 0,
    /// which JSON would read as the integer 0 anyway.
    static std::string number(float value, const std::string& where) {
        if (!std::isfinite(value)) throw std::invalid_argument(where + " is " + numberText(value) + ", which a scene file cannot hold");
        return numberText(value == 0.0f ? 0.0f : value);
    }

    static std::string vec3(const glm::vec3& value, const std::string& where) {
        return "[" + number(value.x, where + "[0]") + ", " + number(value.y, where + "[1]") + ", " +
               number(value.z, where + "[2]") + "]";
    }

    static std::string boolean(bool on) { return on ? "true" : "false"; }

    /// JSON's escapes by nlohmann; bytes that are not UTF-8 become U+FFFD
    /// rather than a file that cannot be read back.
    static std::string string(const std::string& text) {
        return nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    }

    std::string m_out;
};

} // namespace

EditorScene editorSceneFromJson(const std::string& text, const std::string& fileForMessages) {
    const Value root = json::parse(text, fileForMessages, EditorSceneFileLimits::maxNesting);
    return SceneReader(fileForMessages).read(root);
}

std::string editorSceneToJson(const EditorScene& scene) {
    // What the reader would refuse is not written: a saved file loads again.
    if (const std::string problem = scene.idProblem(); !problem.empty()) throw std::invalid_argument(problem);
    return SceneWriter().write(scene);
}

EditorScene loadEditorScene(const fs::path& file) {
    removeStaleSaves(file);
    return editorSceneFromJson(readInputFile(file, EditorSceneFileLimits::maxFileBytes, "a scene file"), file.string());
}

void saveEditorScene(const EditorScene& scene, const fs::path& file) {
    std::string text;
    try {
        text = editorSceneToJson(scene);
    } catch (const std::invalid_argument& error) {
        throw InputError(file.string(), 0, std::string("cannot save the scene: ") + error.what());
    }
    saveFileSafely(file, text, "the scene");
}

} // namespace stoa
