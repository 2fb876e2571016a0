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
    std::uint32_t id = 0;        // > 0, unique among the scene's objects and lights, kept by save and load
    std::string name;
    std::string mesh;            // "shape:cube", "shape:sphere", "shape:cylinder", "shape:plane", or an OBJ asset name
    std::string material;        // the name of one of the scene's materials
    glm::vec3 position{0.0f};
    glm::vec3 rotationDegrees{0.0f};   // about X, then Y, then Z (stoa::modelMatrix)
    glm::vec3 scale{1.0f};
};

/// A point light the editor can move and switch.
struct EditorLight {
    std::uint32_t id = 0;        // > 0, in the same id space as the objects
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 color{1.0f};       // linear RGB, intensity folded in (may exceed 1)
    float radius = 6.0f;         // where its light ends (> 0)
    bool on = true;
};

/// How the editor draws: the course's passes, each on or off.
struct EditorRendererSettings {
    bool deferred = false;       // deferred shading (lab 08) instead of forward
    bool shadows = true;         // the sun's shadow map (lab 05)
    int pcfSize = 3;             // percentage-closer filter width in texels: 1, 3 or 5
    bool normalMaps = true;      // lab 04
    bool ssao = false;           // lab 09
    std::string debugView = "final";   // "final" or a pass's debug view (e.g. "albedo", "normals", "ambient")
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
    static constexpr int kFormatVersion = 1;

    glm::vec3 ambient{0.1f};
    glm::vec3 sunDirection{-0.4f, -1.0f, -0.3f};   // the way the sunlight travels
    glm::vec3 sunColor{1.0f};
    std::vector<EditorMaterial> materials;
    std::vector<EditorObject> objects;
    std::vector<EditorLight> lights;
    std::string crowdWorld;      // a crowd world (lab 10's XML) walking the scene; empty: none
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
    /// One more than the largest id of any object or light (1 for an empty scene).
    std::uint32_t nextId() const;
    /// Appends an object with the next id and returns it (invalidates references into `objects`).
    EditorObject& addObject(std::string name, std::string mesh, std::string material);
    /// Removes the object with `id`; false when there is none.
    bool removeObject(std::uint32_t id);
};

} // namespace stoa
