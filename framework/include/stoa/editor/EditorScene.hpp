#pragma once
// The scene the editor (stoa-editor, lab 11) edits, as plain data: what is
// saved to and loaded from a scene file (EditorSceneFile.hpp), what an undo
// command changes, what the inspector shows. No GL: the editor's renderer
// turns it into drawable objects (and again after every edit).
//
//   EditorScene scene;
//   EditorObject& column = scene.addObject("column", "shape:cylinder", "marble");
//   column.position = {2.0f, 0.0f, -1.0f};

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace stoa {

/// A Blinn-Phong material with optional maps, named so objects can share it.
struct EditorMaterial {
    std::string name;            // unique within the scene
    glm::vec3 diffuse{0.8f};     // k_d, linear RGB in [0, 1]
    glm::vec3 specular{0.2f};    // k_s
    float shininess = 32.0f;     // the Blinn-Phong exponent n, > 0
    std::string diffuseMap;      // asset name under assets/ (e.g. "textures/marble.png"); empty: none
    std::string normalMap;       // asset name of a tangent-space normal map; empty: none
    std::string shader;          // program asset name (e.g. "editor/lit": editor/lit.vert + .frag); empty: the default
};

/// Something drawn: a mesh with a material, placed by position, rotation and scale.
struct EditorObject {
    std::uint32_t id = 0;        // 1 to EditorScene::kMaxId, unique among objects and lights, kept by save and load
    std::string name;
    std::string mesh;            // "shape:cube", "shape:sphere", "shape:cylinder", "shape:plane", or an OBJ asset name
    std::string material;        // the name of one of the scene's materials
    glm::vec3 position{0.0f};
    glm::vec3 rotationDegrees{0.0f};   // about X, then Y, then Z (stoa::modelMatrix)
    glm::vec3 scale{1.0f};
};

/// A point light the editor can move and switch.
struct EditorLight {
    std::uint32_t id = 0;        // 1 to EditorScene::kMaxId, in the same id space as the objects
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 color{1.0f};       // linear RGB, intensity folded in (may exceed 1)
    float radius = 6.0f;         // where its light ends (> 0)
    bool on = true;
};

/// How the editor draws: the course's passes, each on or off. Forward is lab
/// 11's own pass; deferred is every lab's pass in one frame
/// (stoa/render/CourseRenderer.hpp), and the settings below it apply there.
struct EditorRendererSettings {
    bool deferred = false;       // the course pipeline (labs 04-10) instead of lab 11's forward pass
    bool shadows = true;         // the sun's cascaded shadow maps (lab 05)
    int pcfSize = 3;             // lab 05's percentage-closer filter: 1 one tap, 2 the 2x2, 3 the 3x3 texels
    bool normalMaps = true;      // lab 04
    bool ssao = false;           // lab 09
    bool sky = true;             // lab 06's skybox
    bool culling = true;         // lab 06's frustum culling and levels of detail
    std::string debugView = "final";   // "final" or a pass's debug view (CourseRenderer.hpp's courseViewNames())
};

/// A wide field of copies around the scene, jittered on a grid, for lab 06's
/// culling and levels of detail. Not objects: no picking, no edits.
struct EditorField {
    /// The most rows a scene file may ask for: 100 x 100 copies draw in the
    /// deferred pipeline at 1280 x 720 on llvmpipe (2 cores) in 1.8 times the
    /// showcase's frame (20 x 20), measured with showcase_benchmark --scene
    /// (docs/instructor-guide.md, "The editor's caps").
    static constexpr int kMaxRows = 100;
    std::vector<std::string> meshes;   // OBJ assets (or shapes), one picked per copy; empty: no field
    std::string material;              // one of the scene's materials; empty: the default
    int rows = 20;                     // rows x rows places
    float spacing = 10.0f;             // metres between neighbouring places
    float clearRadius = 16.0f;         // no copy within this many metres of the origin (x and z)
    int seed = 6;
};

/// Point lights that wander over the ground in the deferred pipeline (lab 08's
/// hundreds of lights). Not objects: no picking, no edits.
struct EditorLightSwarm {
    /// The most lights a scene file may ask for: 2,000 draw at 1280 x 720 on
    /// llvmpipe (2 cores) in 1.9 times the showcase's frame (300 lights); 4,096
    /// took 3.2 times (docs/instructor-guide.md, "The editor's caps").
    static constexpr int kMaxCount = 2000;
    int count = 0;                     // 0: none
    float radius = 14.0f;              // they stay within this many metres of the origin (x and z)
    float height = 2.5f;               // their paths' centres lie from 0.3 m up to this many metres above y = 0
    float brightness = 1.0f;           // scales every colour (each reaches about 3 to 4.5 m)
    int seed = 1;
};

/// Where the editor's orbit camera looks from.
struct EditorCamera {
    glm::vec3 target{0.0f};
    float distance = 12.0f;
    float yawDegrees = 30.0f;
    float pitchDegrees = 25.0f;
};

struct EditorScene {
    /// The scene-file format this build writes; it reads versions 1 to this.
    static constexpr int kFormatVersion = 2;   // 2: field, light_swarm, renderer.sky and .culling
    /// The largest id of an object or light, 2^24 - 1. A scene file with a
    /// larger id is refused, and nextId() never passes it, so every scene the
    /// editor saves loads again. Ids from 2^24 up are free for things drawn
    /// that are not objects (the editor's field copies in the ids view).
    static constexpr std::uint32_t kMaxId = (1u << 24) - 1;

    glm::vec3 ambient{0.1f};
    glm::vec3 sunDirection{-0.4f, -1.0f, -0.3f};   // the way the sunlight travels
    glm::vec3 sunColor{1.0f};
    std::vector<EditorMaterial> materials;
    std::vector<EditorObject> objects;
    std::vector<EditorLight> lights;
    std::string crowdWorld;      // a crowd world (lab 10's XML, assets/crowds/) walking the scene; empty: none
    EditorField field;
    EditorLightSwarm lightSwarm;
    EditorRendererSettings renderer;
    EditorCamera camera;

    /// The object or light with `id`; nullptr when there is none.
    EditorObject* findObject(std::uint32_t id);
    const EditorObject* findObject(std::uint32_t id) const;
    EditorLight* findLight(std::uint32_t id);
    const EditorLight* findLight(std::uint32_t id) const;
    /// The material called `name`; nullptr when there is none.
    const EditorMaterial* findMaterial(const std::string& name) const;
    EditorMaterial* findMaterial(const std::string& name);
    /// One more than the largest id of any object or light (1 for an empty
    /// scene); when that would pass kMaxId, the smallest id that no object or
    /// light has. Never 0, never past kMaxId. Throws std::length_error when
    /// every id from 1 to kMaxId is taken (a scene file is too small to hold
    /// that many).
    std::uint32_t nextId() const;
    /// The first id a scene file cannot hold, said as "objects[1].id is 0, but
    /// ..." (0, past kMaxId, or the id of another object or light); empty when
    /// every id can be saved.
    std::string idProblem() const;
    /// Appends an object with the next id and returns it (invalidates references into `objects`).
    EditorObject& addObject(std::string name, std::string mesh, std::string material);
    /// Removes the object with `id`; false when there is none.
    bool removeObject(std::uint32_t id);
};

} // namespace stoa
