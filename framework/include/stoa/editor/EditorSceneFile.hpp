#pragma once
// The editor's scene files: an EditorScene as JSON (nlohmann-json). The
// format's reference is docs/scene-files.md and assets/scenes/example.json is
// an example; in short:
//
//   {
//     "stoa_scene": 1,
//     "ambient": [0.1, 0.1, 0.1],
//     "sun": {"direction": [-0.4, -1, -0.3], "color": [1, 1, 1]},
//     "materials": [{"name": "marble", "diffuse_map": "acropolis/column_diffuse.png"}],
//     "objects": [{"id": 1, "name": "column", "mesh": "shape:cylinder", "material": "marble"}],
//     "lights": [{"id": 2, "name": "lamp", "position": [0, 3, 0], "radius": 8}]
//   }
//
// Reading is strict: every problem is an InputError naming the file, the line
// of the offending value and what was expected. JSON that is not well formed,
// a key the format does not know (with the keys allowed there), a value of the
// wrong type, a version newer than this build reads, a missing version, an id
// that is 0, past EditorScene::kMaxId or used twice, an object whose material
// does not exist, a value
// out of its range. A missing key takes the default of its field in
// EditorScene.hpp.
//
// Writing is stable: keys in a fixed order, 2-space indents, a vec3 as
// [x, y, z] on one line, each float in the fewest digits that read back to the
// same float, so that save, load, save again gives the same bytes.

#include <stoa/editor/EditorScene.hpp>

#include <cstddef>
#include <filesystem>
#include <string>

namespace stoa {

/// Limits that keep a hostile file from taking the machine.
struct EditorSceneFileLimits {
    static constexpr std::size_t maxFileBytes = 16u << 20;
    static constexpr int maxNesting = 32;   // objects and arrays inside each other
};

/// The scene in `text`, a scene file's contents; `fileForMessages` is the
/// file named in errors. Reads every version from 1 to EditorScene::kFormatVersion.
EditorScene editorSceneFromJson(const std::string& text, const std::string& fileForMessages);

/// The scene file's text for `scene`, in the current format version.
/// Throws std::invalid_argument naming the field when a number is not finite
/// (NaN or infinity has no JSON spelling) or an id is one the reader refuses
/// (0, past EditorScene::kMaxId, used twice): what is saved loads again.
std::string editorSceneToJson(const EditorScene& scene);

/// Reads the scene file at `file` (at most EditorSceneFileLimits::maxFileBytes).
/// First removes the temporary files that saves of it killed mid-way left
/// beside it (`.NAME.saving-PID-N` of a process that no longer runs).
EditorScene loadEditorScene(const std::filesystem::path& file);

/// Writes `scene` to `file` without ever leaving it half written: the text goes
/// to a temporary file beside it, flushed to the disk, which then replaces it
/// in one rename (a program that dies mid-save leaves the old file whole; the
/// next open or save removes its temporary file). A symbolic link is followed
/// and its target written, so the link stays a link. Throws InputError naming
/// the file when it cannot or must not be written: no such folder, no
/// permission, disk full, a number that is not finite, a bad id, a read-only
/// file, a FIFO, a device, a folder or anything else that is not a regular
/// file, a symbolic link loop. The old file is then unchanged and no temporary
/// file is left.
void saveEditorScene(const EditorScene& scene, const std::filesystem::path& file);

} // namespace stoa
