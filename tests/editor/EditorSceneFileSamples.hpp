#pragma once
// What the editor's scene file tests share (EditorSceneSaveLoadTests.cpp, which
// saves and loads valid scenes, and EditorSceneFileTests.cpp, which checks the
// refusals): a valid version-1 scene file, which each refusal changes in one place
// and whose left-out keys take the defaults, and a plain substring test for the
// messages.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace stoa::test::scene_file {

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The whole of a file, or "" when it cannot be read.
inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A valid scene every refusal in EditorSceneFileTests.cpp changes in one place.
inline const std::string kScene = R"({
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

} // namespace stoa::test::scene_file
