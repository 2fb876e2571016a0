// Lab 11, part 1: picking through the stencil buffer. Read docs/labs/11_editor.md,
// "Picking with the stencil buffer", first.

#include "lab11.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <algorithm>

namespace stoa {

int objectAtPixel(const StencilReadback& stencil, glm::ivec2 mouse, int radiusPixels) {
    // TODO(lab11): a mouse outside the read-back picks nothing (-1). Turn the
    // mouse's row (counted from the top) into a read-back row (counted from
    // the bottom). A value v > 0 there is object v - 1; a 0 is the background:
    // then search the pixels within radiusPixels for the nearest one that
    // holds an object (docs: "A click beside a thin object").
    (void)stencil;
    (void)mouse;
    (void)radiusPixels;
    throw NotImplemented("objectAtPixel()");
}

} // namespace stoa
