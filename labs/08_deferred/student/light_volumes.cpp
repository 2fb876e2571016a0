// Lab 08, part 2: light volumes. Read docs/labs/08_deferred.md, "How far a
// light reaches" and "Light volumes". The app draws, for each light, a sphere
// of radius lightReach(light, cutoff) around it with lightVolumeState(); each
// fragment of that sphere lights the G-buffer pixel under it
// (shaders/deferred/light_volume.frag).

#include "lab08.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/gl/RenderState.hpp>
#include <stoa/render/DeferredShading.hpp>
#include <stoa/scene/Light.hpp>

#include <algorithm>
#include <cmath>

namespace stoa {

float lightReach(const PointLight& light, float cutoff) {
    // TODO(lab08): the brightest channel of light.color, attenuated by
    // 1 / (c + l d + q d^2), equals cutoff at d = the reach: solve the quadratic
    // for its root d >= 0; mind q = 0 (and l = 0 too), and lights never brighter
    // than cutoff (docs: "How far a light reaches").
    (void)light;
    (void)cutoff;
    throw NotImplemented("lightReach()");
}

RenderState lightVolumeState() {
    // TODO(lab08): which faces to cull, which depth test, whether to write
    // depth, how to blend, so that every pixel inside a light's reach gets that
    // light once, with the camera outside the sphere or inside it
    // (docs: "Light volumes"). RenderState's defaults are in stoa/gl/RenderState.hpp.
    throw NotImplemented("lightVolumeState()");
}

} // namespace stoa
