// Lab 11, part 3: undo and redo. Read docs/labs/11_editor.md, "Undo and redo
// as commands", first.

#include "lab11.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <utility>

namespace stoa {

void EditHistory::perform(EditorScene& scene, EditCommand command) {
    // TODO(lab11): apply the command, then record it in m_done. A new edit
    // ends what redo could bring back. Merge it into the latest edit instead
    // when a merge is open and the mergeKeys match (docs: "One drag, one undo").
    (void)scene;
    (void)command;
    throw NotImplemented("EditHistory::perform()");
}

void EditHistory::endMerge() {
    // TODO(lab11): close the open merge.
    throw NotImplemented("EditHistory::endMerge()");
}

bool EditHistory::undo(EditorScene& scene) {
    // TODO(lab11): revert the latest edit and move it over to m_undone.
    (void)scene;
    throw NotImplemented("EditHistory::undo()");
}

bool EditHistory::redo(EditorScene& scene) {
    // TODO(lab11): apply the latest undone edit again and move it back to m_done.
    (void)scene;
    throw NotImplemented("EditHistory::redo()");
}

} // namespace stoa
