// Lab 11's edit history (labs/11_editor/student/lab11.hpp) against a model
// written here:
//   - EditHistory on 400 random sequences of perform / undo / redo / endMerge
//     (commands that set one coordinate of one object, with merge keys per
//     object as the editor makes them) against a model that keeps the scene's
//     states before and after each edit: the scene after every step, the undo
//     and redo counts, the labels, a new edit ending redo, merges only while
//     open and only with an equal non-empty key, undo and redo closing a merge.
// The planted mistakes of solutions/11_editor/mistakes/ for it each fail cases
// here (checked by applying each one's find/replace to a copy of the solutions),
// and the equivalent undo_redo_by_swapping_stacks passes:
//   every_move_its_own_edit    EditHistory "merges", "close a merge", "random sequences"
//   redo_survives_a_new_edit   EditHistory "a new edit ends redo", "random sequences"
// StencilPickTests.cpp, GizmoTests.cpp and HotReloadTests.cpp test the rest of
// the lab's editor core.

#include "catch.hpp"
#include "TestRandom.hpp"

#include "lab11.hpp"

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

using namespace stoa;

namespace {

using Random = stoa::test::Random;

/// The scene the history tests edit: three objects; an edit sets one
/// coordinate (x) of one of them, as the editor's move does.
EditorScene threeObjects() {
    EditorScene scene;
    scene.materials.push_back(EditorMaterial{});
    for (const char* name : {"a", "b", "c"}) scene.addObject(name, "shape:cube", scene.materials.front().name);
    return scene;
}

using State = std::vector<float>;   // each object's x, in the scene's order

State stateOf(const EditorScene& scene) {
    State state;
    for (const EditorObject& object : scene.objects) state.push_back(object.position.x);
    return state;
}

/// The command the editor would make to set object `index`'s x to `value`,
/// its revert the value now (when the command is made). Keyed commands are
/// moves, merged per object ("move 2"); unkeyed ones are other edits.
EditCommand setX(const EditorScene& scene, std::size_t index, float value, bool keyed) {
    const std::uint32_t id = scene.objects[index].id;
    const float before = scene.objects[index].position.x;
    const std::string name = scene.objects[index].name;
    return {keyed ? "move " + name : "set " + name,
            [id, value](EditorScene& s) { s.findObject(id)->position.x = value; },
            [id, before](EditorScene& s) { s.findObject(id)->position.x = before; },
            keyed ? "move " + std::to_string(id) : ""};
}

/// The model: every edit as the scene's states before and after it.
struct ModelEdit {
    State before, after;
    std::string label, key;
};

enum class Merge { Closed, Open, Unknown };

struct ModelHistory {
    State scene;
    std::vector<ModelEdit> done, undone;
    // Whether a merge is open. After an undo or a redo that had nothing to do
    // while a merge was open, the contract ("nothing changes") and the
    // equivalent solution that closes the merge anyway disagree: Unknown, and
    // the sequences below close it before a command that could merge.
    Merge merge = Merge::Closed;
};

} // namespace

// --- EditHistory ------------------------------------------------------------------------

TEST_CASE("Lab 11: EditHistory undoes and redoes edits in order", "[lab11][editor]") {
    EditorScene scene = threeObjects();
    EditHistory history;
    CHECK_FALSE(history.undo(scene));
    CHECK_FALSE(history.redo(scene));
    history.perform(scene, setX(scene, 0, 1.0f, false));
    history.perform(scene, setX(scene, 1, 2.0f, false));
    history.perform(scene, setX(scene, 0, 3.0f, false));
    CHECK(stateOf(scene) == State{3.0f, 2.0f, 0.0f});
    CHECK(history.undoCount() == 3);
    CHECK(history.doneLabels() == std::vector<std::string>{"set a", "set b", "set a"});
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{1.0f, 2.0f, 0.0f});
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{1.0f, 0.0f, 0.0f});
    CHECK(history.undoCount() == 1);
    CHECK(history.redoCount() == 2);
    REQUIRE(history.redo(scene));
    CHECK(stateOf(scene) == State{1.0f, 2.0f, 0.0f});
    REQUIRE(history.undo(scene));
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{0.0f, 0.0f, 0.0f});
    CHECK_FALSE(history.undo(scene));   // nothing left: nothing changes
    CHECK(stateOf(scene) == State{0.0f, 0.0f, 0.0f});
    CHECK(history.redoCount() == 3);
    while (history.redo(scene)) {
    }
    CHECK(stateOf(scene) == State{3.0f, 2.0f, 0.0f});
    CHECK(history.undoCount() == 3);
    CHECK(history.redoCount() == 0);
}

TEST_CASE("Lab 11: EditHistory: a new edit ends redo", "[lab11][editor]") {
    EditorScene scene = threeObjects();
    EditHistory history;
    history.perform(scene, setX(scene, 0, 1.0f, false));
    history.perform(scene, setX(scene, 0, 2.0f, false));
    REQUIRE(history.undo(scene));
    REQUIRE(history.redoCount() == 1);
    history.perform(scene, setX(scene, 1, 5.0f, false));
    CHECK(history.redoCount() == 0);
    CHECK_FALSE(history.redo(scene));
    CHECK(stateOf(scene) == State{1.0f, 5.0f, 0.0f});
    CHECK(history.doneLabels() == std::vector<std::string>{"set a", "set b"});
}

TEST_CASE("Lab 11: EditHistory merges commands with the same key while the merge is open", "[lab11][editor]") {
    EditorScene scene = threeObjects();
    EditHistory history;
    // One drag of a: four moves, one edit.
    for (float x : {1.0f, 2.0f, 3.0f, 4.0f}) history.perform(scene, setX(scene, 0, x, true));
    history.endMerge();
    CHECK(history.undoCount() == 1);
    CHECK(stateOf(scene) == State{4.0f, 0.0f, 0.0f});
    // A second drag of a, after the button went up: a new edit.
    for (float x : {5.0f, 6.0f}) history.perform(scene, setX(scene, 0, x, true));
    CHECK(history.undoCount() == 2);
    // A move of b: another key, another edit; then a again: not the latest key, another edit.
    history.perform(scene, setX(scene, 1, 7.0f, true));
    history.perform(scene, setX(scene, 0, 8.0f, true));
    CHECK(history.undoCount() == 4);
    history.endMerge();
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{6.0f, 7.0f, 0.0f});
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{6.0f, 0.0f, 0.0f});
    REQUIRE(history.undo(scene));   // the whole second drag
    CHECK(stateOf(scene) == State{4.0f, 0.0f, 0.0f});
    REQUIRE(history.undo(scene));   // the whole first drag
    CHECK(stateOf(scene) == State{0.0f, 0.0f, 0.0f});
    // Redo brings the whole drag back, at its last move.
    REQUIRE(history.redo(scene));
    CHECK(stateOf(scene) == State{4.0f, 0.0f, 0.0f});

    // Empty keys never merge, even back to back.
    EditorScene plain = threeObjects();
    EditHistory unkeyed;
    for (float x : {1.0f, 2.0f, 3.0f}) unkeyed.perform(plain, setX(plain, 2, x, false));
    CHECK(unkeyed.undoCount() == 3);
    // An unkeyed edit between two moves of a closes the merge.
    unkeyed.perform(plain, setX(plain, 0, 1.0f, true));
    unkeyed.perform(plain, setX(plain, 1, 1.0f, false));
    unkeyed.perform(plain, setX(plain, 0, 2.0f, true));
    CHECK(unkeyed.undoCount() == 6);
}

TEST_CASE("Lab 11: EditHistory: undo and redo close a merge", "[lab11][editor]") {
    EditorScene scene = threeObjects();
    EditHistory history;
    history.perform(scene, setX(scene, 0, 1.0f, false));
    history.perform(scene, setX(scene, 0, 2.0f, true));
    history.perform(scene, setX(scene, 0, 3.0f, true));
    REQUIRE(history.undoCount() == 2);
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{1.0f, 0.0f, 0.0f});
    // Two moves after the undo: one new edit (the edit before it has no key).
    history.perform(scene, setX(scene, 0, 4.0f, true));
    history.perform(scene, setX(scene, 0, 5.0f, true));
    CHECK(history.undoCount() == 2);
    // Undo, redo: the redone move is not open for merging.
    REQUIRE(history.undo(scene));
    REQUIRE(history.redo(scene));
    CHECK(stateOf(scene) == State{5.0f, 0.0f, 0.0f});
    history.perform(scene, setX(scene, 0, 6.0f, true));
    CHECK(history.undoCount() == 3);
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{5.0f, 0.0f, 0.0f});
    // Undo closes it too: a move (a new edit, the merge open), undone; the next move with
    // the same key as the latest edit (the 5.0 move) is a new edit.
    history.perform(scene, setX(scene, 0, 7.0f, true));
    CHECK(history.undoCount() == 3);
    REQUIRE(history.undo(scene));
    history.perform(scene, setX(scene, 0, 8.0f, true));
    CHECK(history.undoCount() == 3);
    REQUIRE(history.undo(scene));
    CHECK(stateOf(scene) == State{5.0f, 0.0f, 0.0f});
}

TEST_CASE("Lab 11: EditHistory agrees with a model of scene states on 400 random sequences", "[lab11][editor]") {
    Random random(1107);
    int merged = 0, redoneAfterUndo = 0, redoCleared = 0;
    for (int sequence = 0; sequence < 400; ++sequence) {
        EditorScene scene = threeObjects();
        EditHistory history;
        ModelHistory model;
        model.scene = stateOf(scene);
        std::ostringstream steps;
        const int length = 10 + random.below(50);
        for (int step = 0; step < length; ++step) {
            const int what = random.below(10);
            if (what < 5) {   // perform: an edit of one object, keyed (a move) or not
                const std::size_t index = static_cast<std::size_t>(random.below(3));
                const bool keyed = random.chance(0.7f);
                const float value = static_cast<float>(random.below(1000));
                EditCommand command = setX(scene, index, value, keyed);
                const bool sameKey = !model.done.empty() && keyed && model.done.back().key == command.mergeKey;
                if (model.merge == Merge::Unknown && sameKey) {
                    history.endMerge();
                    model.merge = Merge::Closed;
                    steps << "endMerge; ";
                }
                steps << "perform " << command.label << " x=" << value << "; ";
                ModelEdit edit{model.scene, model.scene, command.label, command.mergeKey};
                edit.after[index] = value;
                if (!model.undone.empty()) ++redoCleared;
                model.undone.clear();
                if (model.merge == Merge::Open && sameKey) {
                    model.done.back().after = edit.after;
                    model.done.back().label = edit.label;
                    ++merged;
                } else {
                    model.done.push_back(edit);
                    model.merge = keyed ? Merge::Open : Merge::Closed;
                }
                model.scene = edit.after;
                history.perform(scene, std::move(command));
            } else if (what < 7) {
                steps << "undo; ";
                const bool expected = !model.done.empty();
                if (expected) {
                    model.scene = model.done.back().before;
                    model.undone.push_back(model.done.back());
                    model.done.pop_back();
                    model.merge = Merge::Closed;
                } else if (model.merge == Merge::Open) {
                    model.merge = Merge::Unknown;
                }
                INFO(steps.str());
                REQUIRE(history.undo(scene) == expected);
            } else if (what < 9) {
                steps << "redo; ";
                const bool expected = !model.undone.empty();
                if (expected) {
                    model.scene = model.undone.back().after;
                    model.done.push_back(model.undone.back());
                    model.undone.pop_back();
                    model.merge = Merge::Closed;
                    ++redoneAfterUndo;
                } else if (model.merge == Merge::Open) {
                    model.merge = Merge::Unknown;
                }
                INFO(steps.str());
                REQUIRE(history.redo(scene) == expected);
            } else {
                steps << "endMerge; ";
                history.endMerge();
                model.merge = Merge::Closed;
            }
            INFO("sequence " << sequence << ": " << steps.str());
            REQUIRE(stateOf(scene) == model.scene);
            REQUIRE(history.undoCount() == model.done.size());
            REQUIRE(history.redoCount() == model.undone.size());
            std::vector<std::string> labels;
            for (const ModelEdit& edit : model.done) labels.push_back(edit.label);
            REQUIRE(history.doneLabels() == labels);
        }
        // Undo everything: the scene as it began; redo everything: as it ended.
        const State end = model.undone.empty() ? model.scene : model.undone.front().after;
        while (history.undo(scene)) {
        }
        CHECK(stateOf(scene) == State{0.0f, 0.0f, 0.0f});
        while (history.redo(scene)) {
        }
        CHECK(stateOf(scene) == end);
    }
    // The sequences exercise merges, redo and a new edit after an undo.
    CHECK(merged > 200);
    CHECK(redoneAfterUndo > 200);
    CHECK(redoCleared > 200);
}
