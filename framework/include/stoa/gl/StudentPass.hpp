#pragma once
// A student's function that draws (lab 05's renderShadowPass), run so that GL
// state set behind RenderState is caught instead of silently drawing wrong.
//
// A pass states its whole state in a PassDescription and beginPass() applies it
// through the StateCache (docs/framework.md, "Render state and passes"). A pass
// written the way many tutorials teach (glEnable(GL_DEPTH_TEST),
// glDisable(GL_CULL_FACE), a bind and a glClear) also draws, but the cache never
// learns of those calls, the viewport and the depth mask are whatever the pass
// before left, and the pictures come out a few per cent off with no clue why.
// runStudentPass() puts GL in a state no pass asks for (depth test and writes
// off, nothing culled, no blending) before the call, and afterwards asks GL
// whether its state is what the last beginPass() applied; if not, it throws
// GlStateChanged naming each difference and the function.
//
//   runStudentPass("renderShadowPass", [&] { studentCode().shadows.renderShadowPass(scene, map, depth, matrix); });

#include <stoa/gl/StateCache.hpp>

#include <stdexcept>
#include <string>

namespace stoa {

/// GL state was changed outside RenderState in a student's pass.
class GlStateChanged : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The message for `differences` (StateCache::differencesFromGl()) after `function`.
inline std::string glStateChangedMessage(const std::string& function, const std::string& differences) {
    return "GL state changed outside RenderState in " + function + "(): " + differences +
           ". Describe the pass with a PassDescription and beginPass() instead of calling glEnable, glDisable, "
           "glDepthMask or glDepthFunc yourself (docs/framework.md, \"Render state and passes\")";
}

template <typename Pass>
void runStudentPass(const std::string& function, Pass&& pass) {
    StateCache& cache = StateCache::current();
    cache.apply(RenderState::overlay());   // what no pass asks for: a pass that says its state changes it all
    pass();
    const std::string differences = cache.differencesFromGl();
    if (!differences.empty()) throw GlStateChanged(glStateChangedMessage(function, differences));
}

} // namespace stoa
