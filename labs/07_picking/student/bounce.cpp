// Lab 07, part 4: a ball that bounces off the Acropolis, and its sparks.
// Read docs/labs/07_picking.md, "A bouncing ball", first. The app calls
// advanceSimulation() every frame with the frame's duration; the rest is called
// from there (lab07.hpp says in which order).

#include "lab07.hpp"

#include <stoa/core/NotImplemented.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace stoa {

glm::vec3 closestPointOnTriangle(const glm::vec3& point, const Triangle& triangle) {
    // TODO(lab07): find the region of the point: beyond a corner, beyond an edge,
    // or above the face, from the signs of dot products of the edges with the
    // point's offsets from the corners; return that corner, the projection on
    // that edge, or the projection on the face (docs: "Closest point on a triangle").
    (void)point;
    (void)triangle;
    throw NotImplemented("closestPointOnTriangle()");
}

void trianglesNearSphere(const Bvh& bvh, const BoundingSphere& sphere, std::vector<int>& out) {
    // TODO(lab07): the sphere's box is centre -+ radius on every axis. Walk the
    // tree from the root with a stack, going into the nodes whose boxes overlap
    // it (overlap on every axis: box.min <= high and box.max >= low); a leaf's
    // triangles all go into `out` (docs: "Finding the triangles").
    (void)bvh;
    (void)sphere;
    (void)out;
    throw NotImplemented("trianglesNearSphere()");
}

std::optional<Contact> stepBall(Ball& ball, const Bvh& bvh, float seconds, const BounceSettings& settings) {
    // TODO(lab07): velocity += gravity * seconds, then position += velocity * seconds.
    // Of the triangles near the ball, the one whose closest point is nearest the
    // centre, if nearer than the radius: the normal from that point to the
    // centre; move the ball out to touching; if it moves into the surface
    // (speed = -dot(velocity, normal) > 0) reflect that part with the
    // restitution and return the contact (docs: "A bouncing ball").
    (void)ball;
    (void)bvh;
    (void)seconds;
    (void)settings;
    throw NotImplemented("stepBall()");
}

void stepParticles(std::vector<Particle>& particles, float seconds, const BounceSettings& settings) {
    // TODO(lab07): move every particle as stepBall() moves the ball (no
    // collisions), add `seconds` to its age, then remove the ones whose age has
    // reached their lifetime, keeping the others in order (std::remove_if)
    // (docs: "Sparks").
    (void)particles;
    (void)seconds;
    (void)settings;
    throw NotImplemented("stepParticles()");
}

void advanceSimulation(Simulation& simulation, const Bvh& bvh, float frameSeconds) {
    // TODO(lab07): add the frame's time to the accumulator; while it holds a
    // whole step: stepBall(); for a contact faster than settings.sparkSpeed,
    // spawnSparks() (lab07.hpp) with simulation.random and count it in
    // simulation.contacts; stepParticles(); take the step off the accumulator and
    // add it to simulation.time (docs: "A fixed time step").
    (void)simulation;
    (void)bvh;
    (void)frameSeconds;
    throw NotImplemented("advanceSimulation()");
}

} // namespace stoa
