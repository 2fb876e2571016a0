// Lab 11's property checks; see checks.hpp. They call your objectAtPixel(),
// EditHistory and assetsToReload() on data of their own and test a rule the
// docs state.

#include "checks.hpp"

#include "lab11.hpp"

#include <string>
#include <vector>

namespace lab11 {

namespace {

using stoa::CheckResult;

/// A read-back of `width` x `height` zeros, bottom row first.
stoa::StencilReadback background(int width, int height) {
    return {width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height, 0)};
}

/// Sets the value at window pixel (x, y) (from the top-left corner).
void put(stoa::StencilReadback& stencil, int x, int y, std::uint8_t value) {
    stencil.values[static_cast<std::size_t>(stencil.height - 1 - y) * stencil.width + x] = value;
}

std::string pixel(int x, int y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

// A failed check says which section of the lab page states the rule.
CheckResult pointingToDocs(CheckResult result, const std::string& section) {
    if (!result.holds && result.message.find("(docs:") == std::string::npos)
        result.message += " (docs: " + section + ")";
    return result;
}

CheckResult pickWithinACircleBody() {
    stoa::StencilReadback stencil = background(21, 15);
    if (stoa::objectAtPixel(stencil, {10, 7}, 4) != -1)
        return CheckResult::fail("a click on the background with nothing within the radius picked an object");
    put(stencil, 14, 7, 3);   // exactly 4 pixels to the right of (10, 7)
    if (int got = stoa::objectAtPixel(stencil, {10, 7}, 4); got != 2)
        return CheckResult::fail("value 3 exactly 4 pixels away, radius 4: expected object 2, got " + std::to_string(got));
    if (int got = stoa::objectAtPixel(stencil, {10, 7}, 3); got != -1)
        return CheckResult::fail("value 3 4 pixels away, radius 3: expected nothing (-1), got " + std::to_string(got));
    // The same along the column, above and below: rows count as columns do.
    for (const int dy : {-4, 4, -3, 3}) {
        stencil = background(21, 15);
        put(stencil, 10, 7 + dy, 4);
        if (int got = stoa::objectAtPixel(stencil, {10, 7}, 4); got != 3)
            return CheckResult::fail("value 4 alone, " + std::to_string(std::abs(dy)) + " pixels " +
                                     (dy < 0 ? "above" : "below") + " the click at " + pixel(10, 7) +
                                     ", radius 4: expected object 3, got " + std::to_string(got) +
                                     " (the circle dx^2 + dy^2 <= R^2 holds rows as far as columns, its edge included)");
    }
    stencil = background(21, 15);
    put(stencil, 14, 8, 5);   // 4 right, 1 down: sqrt(17) pixels away, just outside the circle of radius 4
    if (int got = stoa::objectAtPixel(stencil, {10, 7}, 4); got != -1)
        return CheckResult::fail("value 5 at " + pixel(14, 8) + ", sqrt(17) = 4.12 pixels from the click at " +
                                 pixel(10, 7) + ", radius 4: expected nothing (dx^2 + dy^2 = 17 > R^2 = 16), got " +
                                 std::to_string(got));
    stencil = background(21, 15);
    put(stencil, 13, 4, 5);   // 3 right, 3 up: 4.24 pixels away, inside the square of side 2 x 4, outside the circle
    if (int got = stoa::objectAtPixel(stencil, {10, 7}, 4); got != -1)
        return CheckResult::fail("value 5 at " + pixel(13, 4) + ", 4.24 pixels from the click at " + pixel(10, 7) +
                                 ", radius 4: expected nothing (the radius is a circle, not a square), got " + std::to_string(got));
    stencil = background(21, 15);
    put(stencil, 10, 5, 7);   // 2 above the click
    put(stencil, 10, 9, 8);   // 2 below: the same distance, and first in the read-back (bottom rows first)
    if (int got = stoa::objectAtPixel(stencil, {10, 7}, 4); got != 7)
        return CheckResult::fail("values 7 two pixels above and 8 two pixels below the click: of equally near pixels "
                                 "the first in the read-back's order (the bottom rows first) wins, expected object 7, got " +
                                 std::to_string(got));
    put(stencil, 10, 7, 1);
    if (int got = stoa::objectAtPixel(stencil, {10, 7}, 4); got != 0)
        return CheckResult::fail("value 1 under the mouse: expected object 0, got " + std::to_string(got));
    for (const glm::ivec2 outside : {glm::ivec2(-1, 7), glm::ivec2(21, 7), glm::ivec2(10, -1), glm::ivec2(10, 15)})
        if (int got = stoa::objectAtPixel(stencil, outside, 4); got != -1)
            return CheckResult::fail("a mouse outside the read-back at " + pixel(outside.x, outside.y) +
                                     " picked object " + std::to_string(got));
    // The picture's own corners are pixels like any other: a click on an object there picks it.
    stencil = background(21, 15);
    const glm::ivec2 corners[] = {{0, 0}, {20, 0}, {0, 14}, {20, 14}};
    for (std::size_t i = 0; i < 4; ++i) put(stencil, corners[i].x, corners[i].y, static_cast<std::uint8_t>(i + 2));
    for (std::size_t i = 0; i < 4; ++i)
        if (int got = stoa::objectAtPixel(stencil, corners[i], 0); got != static_cast<int>(i + 1))
            return CheckResult::fail("value " + std::to_string(i + 2) + " under the mouse at the picture's corner " +
                                     pixel(corners[i].x, corners[i].y) + ", radius 0: expected object " +
                                     std::to_string(i + 1) + ", got " + std::to_string(got) +
                                     "; the first and last rows and columns are inside the read-back "
                                     "(docs: From the mouse to a stencil value)");
    // An object only along one edge of the picture, a click two pixels inside it,
    // radius 3: the search reaches the edge's own row or column, and no further.
    struct Edge {
        const char* name;
        glm::ivec2 first, step, click;
    };
    const Edge edges[] = {{"left column", {0, 0}, {0, 1}, {2, 7}},
                          {"right column", {20, 0}, {0, 1}, {18, 7}},
                          {"top row", {0, 0}, {1, 0}, {10, 2}},
                          {"bottom row", {0, 14}, {1, 0}, {10, 12}}};
    for (const Edge& edge : edges) {
        stencil = background(21, 15);
        for (glm::ivec2 at = edge.first; at.x < 21 && at.y < 15; at += edge.step) put(stencil, at.x, at.y, 4);
        if (int got = stoa::objectAtPixel(stencil, edge.click, 3); got != 3)
            return CheckResult::fail("value 4 only along the picture's " + std::string(edge.name) + ", a click at " +
                                     pixel(edge.click.x, edge.click.y) + " 2 pixels from it, radius 3: expected "
                                     "object 3, got " + std::to_string(got) + "; the search runs from 0 to width - 1 "
                                     "and height - 1, the edges included (docs: From the mouse to a stencil value)");
    }
    // Just past the right edge, the next row's first pixel follows in memory.
    stencil = background(21, 15);
    for (int y = 0; y < 15; ++y) put(stencil, 0, y, 6);
    if (int got = stoa::objectAtPixel(stencil, {21, 7}, 0); got != -1)
        return CheckResult::fail("a mouse at " + pixel(21, 7) + ", one past the right edge of a read-back 21 wide, "
                                 "with objects along the left column, picked object " + std::to_string(got) +
                                 ": x = width is outside (docs: From the mouse to a stencil value)");
    // A row's neighbours in memory are the ends of the rows around it: a search
    // that runs past the left or right edge reads the other side of the picture.
    for (const int side : {0, 1}) {
        stencil = background(21, 15);
        for (int y = 0; y < 15; ++y)
            for (int x = 0; x < 3; ++x) put(stencil, side == 0 ? 20 - x : x, y, 6);
        const glm::ivec2 click(side == 0 ? 0 : 20, 7);
        if (int got = stoa::objectAtPixel(stencil, click, 3); got != -1)
            return CheckResult::fail("value 6 only in the three columns at the " + std::string(side == 0 ? "right" : "left") +
                                     " edge, a click at " + pixel(click.x, click.y) + " on the other edge, radius 3: "
                                     "expected nothing (-1), got " + std::to_string(got) +
                                     "; keep the search's columns within 0 to width - 1, or it reads the next "
                                     "row's pixels (docs: From the mouse to a stencil value)");
    }
    // Past the read-back's last row: two guard rows of values after the picture (the
    // read-back says 15 rows): a search that runs past the top reads it.
    stencil = background(21, 15);
    stencil.values.resize(static_cast<std::size_t>(21) * 17, 9);   // two rows past it
    for (const glm::ivec2 click : {glm::ivec2(10, 0), glm::ivec2(10, 1)})
        if (int got = stoa::objectAtPixel(stencil, click, 3); got != -1)
            return CheckResult::fail("a click at " + pixel(click.x, click.y) + " near the top of a read-back with no "
                                     "object, radius 3, picked object " + std::to_string(got) +
                                     "; keep the search's rows within 0 to height - 1, or it reads past the "
                                     "read-back (docs: From the mouse to a stencil value)");
    return CheckResult::pass("the radius is a circle including its edge, ties go to the read-back's order, "
                             "the background and outside pick nothing, the corners and edges pick what is there, "
                             "and the search stays within its row at the edges");
}

CheckResult mergeRulesBody() {
    stoa::EditorScene scene;
    const std::uint32_t id = scene.addObject("box", "shape:cube", "").id;
    const auto x = [&] { return scene.findObject(id)->position.x; };
    // A command that moves the box from where it is to `to`.
    const auto move = [&](float to, const std::string& key) {
        const float from = x();
        return stoa::EditCommand{"move to " + std::to_string(to),
                                 [id, to](stoa::EditorScene& s) { s.findObject(id)->position.x = to; },
                                 [id, from](stoa::EditorScene& s) { s.findObject(id)->position.x = from; }, key};
    };
    stoa::EditHistory history;
    history.perform(scene, move(1.0f, "drag"));
    history.perform(scene, move(2.0f, "drag"));
    history.perform(scene, move(3.0f, "drag"));
    if (history.undoCount() != 1)
        return CheckResult::fail("three moves with the key 'drag' while the merge was open: expected 1 edit, got " +
                                 std::to_string(history.undoCount()));
    if (history.doneLabels().back() != "move to 3.000000")
        return CheckResult::fail("a merged edit keeps the latest command's label: expected 'move to 3.000000', got '" +
                                 history.doneLabels().back() + "'");
    history.endMerge();
    history.perform(scene, move(4.0f, "drag"));
    if (history.undoCount() != 2) return CheckResult::fail("after endMerge(), a command with the same key must be a new edit");
    history.perform(scene, move(5.0f, "other"));
    if (history.undoCount() != 3) return CheckResult::fail("a command with another key must be a new edit");
    history.perform(scene, move(6.0f, ""));
    history.perform(scene, move(7.0f, "other"));
    if (history.undoCount() != 5)
        return CheckResult::fail("a command without a key closes the merge: the next 'other' must be a new edit "
                                 "(expected 5 edits, got " + std::to_string(history.undoCount()) + ")");
    while (history.undo(scene)) {}
    if (x() != 0.0f)
        return CheckResult::fail("undoing every edit must bring the box back to 0, it is at " + std::to_string(x()) +
                                 " (a merged edit reverts to before its first command)");
    history.redo(scene);
    if (x() != 3.0f)
        return CheckResult::fail("redo of the merged drag must move the box to where its last command put it (3), got " +
                                 std::to_string(x()));
    // A redone edit is done again: undo takes it back.
    if (history.undoCount() != 1 || !history.undo(scene) || x() != 0.0f)
        return CheckResult::fail("after redo() of the merged drag, undo() must take it back again (the box to 0, " +
                                 std::to_string(history.undoCount()) + " edits to undo, the box at " +
                                 std::to_string(x()) + "): redo moves the command back onto the done list");
    // The rest redo in order, each once, and then there is nothing left to redo.
    for (int i = 0; i < 8 && history.redo(scene); ++i) {}
    if (history.undoCount() != 5 || x() != 7.0f || history.redo(scene))
        return CheckResult::fail("after undoing all five edits and redoing them all, expected 5 edits done and the "
                                 "box at 7, got " + std::to_string(history.undoCount()) + " and " +
                                 std::to_string(x()) + ": each redo() takes the edit it applies off the undone list "
                                 "(docs: One drag, one undo)");

    // Undo in the middle of a drag: the drag goes on after it, and its next moves
    // are a new edit, not part of the edit before the undone one (which has the same key).
    stoa::EditHistory midDrag;
    midDrag.perform(scene, move(10.0f, "drag"));
    midDrag.endMerge();
    midDrag.perform(scene, move(11.0f, "drag"));
    midDrag.perform(scene, move(12.0f, "drag"));
    midDrag.undo(scene);
    midDrag.perform(scene, move(13.0f, "drag"));
    if (midDrag.undoCount() != 2)
        return CheckResult::fail("a drag to 10, endMerge(), a drag to 11 and 12, undo() in the middle of it, then a move "
                                 "to 13 with the same key: expected 2 edits, got " + std::to_string(midDrag.undoCount()) +
                                 ". undo() closes the merge: the move after it is a new edit, even with the key of the "
                                 "edit now on top (docs: One drag, one undo)");
    midDrag.undo(scene);
    if (x() != 10.0f)
        return CheckResult::fail("undoing the move to 13 made after an undo in the middle of a drag must bring the box "
                                 "back to 10, it is at " + std::to_string(x()) + " (docs: One drag, one undo)");
    return CheckResult::pass("merges only while open with equal keys; endMerge, a keyless command and undo close it; "
                             "a merged edit undoes to before its first command and redoes to after its last; "
                             "every undone edit redoes once, in order");
}

CheckResult reloadBoundariesBody() {
    using stoa::AssetFiles;
    using stoa::FileChange;
    const std::vector<AssetFiles> assets = {{"b", {"/s/b.png"}, 1.0}, {"a", {"/s/a.frag", "/s/common.glsl"}, 1.0},
                                            {"c", {"/s/c.png"}, 2.0}};
    const auto due = [&](const std::vector<FileChange>& changes, double now) {
        std::string names;
        for (const std::string& name : stoa::assetsToReload(changes, assets, now, 0.25)) names += (names.empty() ? "" : " ") + name;
        return names;
    };
    if (std::string got = due({{"/s/common.glsl", 1.5}}, 1.75); got != "a")
        return CheckResult::fail("a change exactly debounceSeconds (0.25) before now is quiet: expected 'a', got '" + got + "'");
    if (std::string got = due({{"/s/common.glsl", 1.5}}, 1.74); !got.empty())
        return CheckResult::fail("a change 0.24 s before now is not quiet (debounce 0.25): expected nothing, got '" + got + "'");
    if (std::string got = due({{"/s/c.png", 2.0}}, 5.0); !got.empty())
        return CheckResult::fail("a change at the asset's loadedAt is loaded already: expected nothing, got '" + got + "'");
    if (std::string got = due({{"/s/other.png", 1.5}}, 5.0); !got.empty())
        return CheckResult::fail("a change to a file no asset uses: expected nothing, got '" + got + "'");
    const std::vector<FileChange> many = {{"/s/a.frag", 1.1}, {"/s/b.png", 1.2}, {"/s/common.glsl", 1.3},
                                          {"/s/a.frag", 1.4}, {"/s/b.png", 1.45}};
    if (std::string got = due(many, 3.0); got != "b a")
        return CheckResult::fail("changes to b and to both of a's files: expected 'b a' (each once, in the assets' order), got '" +
                                 got + "'");
    return CheckResult::pass("quiet at exactly debounceSeconds, changes at loadedAt and to unused files ignored, "
                             "each due asset once in the assets' order");
}

} // namespace

CheckResult checkPickWithinACircle() { return pointingToDocs(pickWithinACircleBody(), "A click beside a thin object"); }

CheckResult checkMergeRules() { return pointingToDocs(mergeRulesBody(), "One drag, one undo"); }

CheckResult checkReloadBoundaries() { return pointingToDocs(reloadBoundariesBody(), "Waiting for quiet"); }

} // namespace lab11
