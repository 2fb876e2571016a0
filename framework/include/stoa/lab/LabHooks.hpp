#pragma once
// Where a lab plugs its own code into the framework at run time. Student
// functions are otherwise resolved when a lab program links, so a framework
// renderer that called lab 06's culling function directly would make labs
// 01-05 fail to link. Instead the lab that has the function hands it over
// here (Lab::hooks()), and a renderer calls it when it is set:
//
//   // in the app of a lab that has a culling function and draws with ForwardRenderer
//   m_hooks.isVisible = [](const BoundingSphere& sphere, const glm::mat4& viewProjection) {
//       return sphereInFrustum(extractFrustumPlanes(viewProjection), sphere);   // the student's
//   };
//   m_renderer.hooks = &m_hooks;
//
// Every hook is optional: unset, the renderer does what it did without it.

#include <stoa/geometry/Bounds.hpp>
#include <stoa/scene/Light.hpp>

#include <glm/mat4x4.hpp>

#include <functional>
#include <vector>

namespace stoa {

class Camera;

struct LabHooks {
    /// Visibility (lab 06): false when an object whose world-space bounding
    /// sphere is `sphere` lies outside what `viewProjection` (world -> clip)
    /// sees. Unset: every object is drawn.
    std::function<bool(const BoundingSphere& sphere, const glm::mat4& viewProjection)> isVisible;
    /// Light culling (lab 08): the indices into `lights` of the point lights
    /// that can reach what `camera` sees. Unset: every light (up to the maximum).
    std::function<std::vector<int>(const std::vector<PointLight>& lights, const Camera& camera)> cullLights;
    /// Agents (lab 10): advances the lab's agents by `seconds` of simulated
    /// time; the window calls it at fixed steps, after the lab's update().
    std::function<void(float seconds)> stepAgents;
};

} // namespace stoa
