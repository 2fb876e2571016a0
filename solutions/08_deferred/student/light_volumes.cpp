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
    const float peak = std::max({light.color.r, light.color.g, light.color.b});
    const float c = light.attenuation.x, l = light.attenuation.y, q = light.attenuation.z;
    // peak / (c + l d + q d^2) = cutoff  <=>  q d^2 + l d + (c - peak / cutoff) = 0.
    const float k = c - peak / cutoff;
    if (k >= 0.0f) return 0.0f;   // never brighter than the cut-off, not even at d = 0
    if (q > 0.0f) return (-l + std::sqrt(l * l - 4.0f * q * k)) / (2.0f * q);
    if (l > 0.0f) return -k / l;
    return 1e30f;                 // no fall-off: it reaches everything
}

RenderState lightVolumeState() {
    RenderState state;
    // The sphere's back faces: there is one behind every pixel the sphere covers,
    // also when the camera is inside it (its front faces are then behind the eye).
    state.cull = CullMode::Front;
    // A back face lights the surface in front of it: the stored depth is nearer.
    state.depth.test = true;
    state.depth.func = GL_GEQUAL;
    state.depth.write = false;
    // Each light adds to what the ambient pass and the other lights left.
    state.blend = BlendMode::Additive;
    return state;
}

} // namespace stoa
