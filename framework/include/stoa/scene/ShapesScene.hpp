#pragma once
// The test scene of labs 01 and 02: a floor and the five procedural shapes,
// rotated and scaled (one non-uniformly) so that every part of the model matrix
// shows, each in its own material.
//
//        torus (tilted)     sphere (squashed)
//   cube (turned)      cylinder         small cube (rolled)
//   ---------------------- floor ----------------------

#include <stoa/scene/Scene.hpp>

namespace stoa {

/// Clears `scene` and fills it with the objects above; the lights are left to the lab.
void buildShapesScene(Scene& scene);

} // namespace stoa
