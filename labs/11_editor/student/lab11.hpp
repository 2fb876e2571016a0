#pragma once
// Lab 11: the scene editor's core operations, in four files. The app
// (editor_app.hpp) and stoa-editor call them; docs/labs/11_editor.md explains
// each one.
//
//   stencil_pick.cpp  objectAtPixel()        which object is under the mouse
//   gizmo.cpp         closestAxisParameter() where the mouse ray passes an axis
//                     dragAlongAxis()        an object dragged along that axis
//   history.cpp       EditHistory            undo and redo as commands
//   hot_reload.cpp    assetsToReload()       which assets to load again now

#include <stoa/assets/ReloadPlan.hpp>
#include <stoa/editor/EditorScene.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace stoa {

// --- stencil_pick.cpp -----------------------------------------------------

/// The stencil buffer read back after the editor's pick pass, which drew the
/// i-th object of its list with stencil value i + 1 (at most 255 objects) over
/// a background of 0. `values` holds width * height bytes, row by row from the
/// BOTTOM row up (the order glReadPixels returns), each row left to right.
struct StencilReadback {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> values;
};

/// The index in the pick pass's list of the object under `mouse` (window
/// pixels: from the TOP-left corner, x right, y down), or -1 for none. When
/// the pixel itself shows the background, the nearest pixel within
/// `radiusPixels` (Euclidean distance between pixel positions) that shows an
/// object decides, so that a click just beside a thin object still takes it;
/// of equally near pixels, the one met first in the read-back's order wins
/// (in the picture: the lowest row first, then the leftmost pixel).
/// A mouse position outside the read-back picks nothing.
int objectAtPixel(const StencilReadback& stencil, glm::ivec2 mouse, int radiusPixels);

// --- gizmo.cpp --------------------------------------------------------------

/// A line through `point` along `direction` (not necessarily of unit length).
struct Line {
    glm::vec3 point{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
};

/// The parameter s of the point axis.point + s * normalize(axis.direction) of
/// the axis that comes closest to the mouse ray (as infinite lines); nullopt
/// when the ray and the axis are parallel or nearly so (the sine of the angle
/// between them below 1e-3), where no point is closest. Neither direction is
/// of length 0.
std::optional<float> closestAxisParameter(const Line& mouseRay, const Line& axis);

/// Where an object that was at `startPosition` when the mouse went down on its
/// gizmo's `axisDirection` arrow (ray `pressRay`) is now that the mouse ray is
/// `currentRay`: moved along the axis by the difference of the two closest
/// parameters, so that the point grabbed stays under the mouse. The axis
/// passes through startPosition. When either parameter does not exist, the
/// object stays at startPosition.
glm::vec3 dragAlongAxis(const glm::vec3& startPosition, const glm::vec3& axisDirection, const Line& pressRay,
                        const Line& currentRay);

// --- history.cpp ------------------------------------------------------------

/// One edit, as the pair of functions that do and undo it. The editor makes
/// them (moving an object, changing its material, deleting it, ...); the
/// history only calls them.
struct EditCommand {
    std::string label;                          // shown in the log, e.g. "move column"
    std::function<void(EditorScene&)> apply;    // makes the edit
    std::function<void(EditorScene&)> revert;   // takes it back: the scene is as before apply
    std::string mergeKey;                       // see EditHistory::perform(); empty: never merges
};

/// Undo and redo (the Command pattern of Gamma et al. 1994): every edit goes
/// through perform(); undo() reverts the latest one still done, redo()
/// applies again the latest one undone.
class EditHistory {
public:
    /// Applies `command` to `scene` and records it as the latest edit; what
    /// was undone before can no longer be redone. While a merge is open (see
    /// below) and `command` has the same non-empty mergeKey as the latest
    /// edit, the two become ONE edit: undo takes both back at once (a drag
    /// sends a command at every mouse move; the whole drag is one undo step).
    /// The merged edit keeps the first command's revert (back to before the
    /// drag) and takes the new command's apply and label.
    /// A command with a non-empty mergeKey opens a merge (when it does not
    /// merge into the latest edit); one with an empty mergeKey, endMerge(),
    /// undo() and redo() close it.
    void perform(EditorScene& scene, EditCommand command);
    /// Closes the open merge (the mouse button went up): the next command is a
    /// new edit even with the same mergeKey.
    void endMerge();
    /// Reverts the latest edit still done (and closes the merge); false (and
    /// nothing changes) when none is.
    bool undo(EditorScene& scene);
    /// Applies again the latest edit undone (and closes the merge); false (and
    /// nothing changes) when none is.
    bool redo(EditorScene& scene);

    std::size_t undoCount() const { return m_done.size(); }
    std::size_t redoCount() const { return m_undone.size(); }
    /// The labels of the edits done, oldest first (for the editor's log).
    std::vector<std::string> doneLabels() const {
        std::vector<std::string> labels;
        for (const EditCommand& command : m_done) labels.push_back(command.label);
        return labels;
    }

private:
    std::vector<EditCommand> m_done;     // oldest first; back() is the latest edit
    std::vector<EditCommand> m_undone;   // back() is the edit redo() applies
    bool m_mergeOpen = false;
};

// --- hot_reload.cpp ---------------------------------------------------------

/// The names of the assets to load again at time `now` (seconds), in the order
/// of `assets`, each once. An asset is due when one of its files changed after
/// the asset was last loaded (change.seconds > loadedAt) and all of its files
/// have been quiet since: no change to any of them later than
/// now - debounceSeconds. Changes to files no asset uses are ignored.
std::vector<std::string> assetsToReload(const std::vector<FileChange>& changes, const std::vector<AssetFiles>& assets,
                                        double now, double debounceSeconds);

} // namespace stoa
