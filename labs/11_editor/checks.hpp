#pragma once
// Lab 11's property checks (the cases with a `check` key in cases.ini), for
// the rules the pictures show only in some cases. See docs/labs/11_editor.md, "Checks".

#include <stoa/lab/PropertyCheck.hpp>

namespace lab11 {

/// pick_within_a_circle: objectAtPixel() on small hand-made read-backs: a
/// pixel exactly radiusPixels away counts, one on the square's corner beyond
/// it does not; of two equally near pixels the first in the read-back's order
/// wins; the background and a mouse outside pick nothing.
stoa::CheckResult checkPickWithinACircle();

/// merge_rules: EditHistory merges a command into the latest edit only while
/// a merge is open and the non-empty keys match; endMerge(), a command without
/// a key and undo() close it; undo of a merged edit goes back to before its
/// first command, redo to after its last.
stoa::CheckResult checkMergeRules();

/// reload_boundaries: assetsToReload() counts a change exactly debounceSeconds
/// old as quiet, a change at loadedAt as already loaded, ignores files no
/// asset uses, and names each due asset once, in the assets' order.
stoa::CheckResult checkReloadBoundaries();

} // namespace lab11
