// Lab 11, part 3: undo and redo. Read docs/labs/11_editor.md, "Undo and redo
// as commands", first.

#include "lab11.hpp"

#include <utility>

namespace stoa {

void EditHistory::perform(EditorScene& scene, EditCommand command) {
    command.apply(scene);
    m_undone.clear();
    if (m_mergeOpen && !command.mergeKey.empty() && !m_done.empty() && m_done.back().mergeKey == command.mergeKey) {
        // One edit from the first command's state to this one's: keep the
        // first revert (back to before the drag), take the latest apply.
        m_done.back().apply = std::move(command.apply);
        m_done.back().label = std::move(command.label);
        return;
    }
    m_mergeOpen = !command.mergeKey.empty();
    m_done.push_back(std::move(command));
}

void EditHistory::endMerge() { m_mergeOpen = false; }

bool EditHistory::undo(EditorScene& scene) {
    if (m_done.empty()) return false;
    m_mergeOpen = false;
    m_done.back().revert(scene);
    m_undone.push_back(std::move(m_done.back()));
    m_done.pop_back();
    return true;
}

bool EditHistory::redo(EditorScene& scene) {
    if (m_undone.empty()) return false;
    m_mergeOpen = false;
    m_undone.back().apply(scene);
    m_done.push_back(std::move(m_undone.back()));
    m_undone.pop_back();
    return true;
}

} // namespace stoa
