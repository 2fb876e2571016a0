#pragma once
// Lab 08: everything you write (light_volumes.cpp, tiled_lights.cpp; the G-buffer is
// g_buffer.glsl). docs/labs/08_deferred.md derives each function. The lab's app, the tests and
// later labs include this header; your files define what it declares.

#include <stoa/gl/RenderState.hpp>
#include <stoa/render/DeferredShading.hpp>
#include <stoa/scene/Light.hpp>

#include <glm/mat4x4.hpp>

#include <vector>

namespace stoa {

/// The distance d >= 0 at which the light's brightest colour channel,
/// attenuated by 1 / (constant + linear d + quadratic d^2), has fallen to
/// `cutoff`; 0 when it is never brighter than `cutoff`. (light_volumes.cpp)
float lightReach(const PointLight& light, float cutoff);

/// The state the light-volume pass draws each light's sphere with: which
/// faces, which depth test, what blending, so that each lit pixel gets the
/// light once, also when the camera is inside the sphere. (light_volumes.cpp)
RenderState lightVolumeState();

/// The tiles of `grid` that a light's sphere can cover, seen through
/// `projection` (view -> clip, near plane at distance `near`): conservative (a
/// tile it covers is never left out), every tile when the sphere crosses the
/// near plane, and empty when it lies wholly nearer than the near plane (or
/// behind the eye) or outside the picture. (tiled_lights.cpp)
TileRange lightTileRange(const LightSphere& light, const glm::mat4& projection, float near, const TileGrid& grid);

/// Every tile's list of the lights whose lightTileRange() holds it and whose
/// sphere reaches into the tile's depth range: tileDepths[t] is tile t's
/// (grid.index() order), and a light whose distances from -centerView.z - reach
/// to -centerView.z + reach miss it cannot light any of the tile's pixels.
/// (tiled_lights.cpp)
TileLightLists buildTileLightLists(const std::vector<LightSphere>& lights, const glm::mat4& projection, float near,
                                   const TileGrid& grid, const std::vector<DepthRange>& tileDepths);

} // namespace stoa
