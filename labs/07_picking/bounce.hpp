#pragma once
// Lab 07, part 4: a ball that falls through the Acropolis, bounces off the
// triangles your BVH finds near it, and throws sparks where it hits; written in
// bounce.cpp (the sparks' billboards are particles.glsl). The app (lab.cpp) and
// the tests include this header; docs/labs/07_picking.md, "A bouncing ball",
// explains the physics.
//
// Every frame the app calls advanceSimulation(simulation, bvh, frameSeconds),
// which runs as many fixed steps of simulation.settings.step as the frames
// have added up to, each one:
//   contact = stepBall(ball, bvh, step, settings)   // trianglesNearSphere, closestPointOnTriangle
//   if (contact && contact->speed > settings.sparkSpeed) spawnSparks(*contact, random, settings, particles)
//   stepParticles(particles, step, settings)

#include "picking.hpp"

#include <stoa/geometry/Bounds.hpp>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace stoa {

struct Ball {
    glm::vec3 position{0.0f};
    glm::vec3 velocity{0.0f};
    float radius = 0.3f;
};

struct Particle {
    glm::vec3 position{0.0f};
    glm::vec3 velocity{0.0f};
    float age = 0.0f;        // seconds since it was spawned
    float lifetime = 1.0f;   // it is removed once age >= lifetime
};

/// Where the ball touched a triangle during a step.
struct Contact {
    glm::vec3 point{0.0f};    // on the triangle
    glm::vec3 normal{0.0f};   // unit, from the triangle towards the ball's centre
    float speed = 0.0f;       // the ball's speed into the surface before the bounce (>= 0)
};

struct BounceSettings {
    float step = 1.0f / 120.0f;               // seconds per fixed step
    glm::vec3 gravity{0.0f, -9.81f, 0.0f};    // m/s^2
    float restitution = 0.6f;                 // the share of the normal speed the bounce keeps
    float sparkSpeed = 1.0f;                  // m/s into the surface needed to throw sparks
    int sparksPerContact = 40;
    float sparkSpeedScale = 0.8f;             // a spark leaves at up to this times the contact's speed
    float sparkLifetime = 0.8f;               // seconds, on average
};

/// Random numbers from a seed, the same on every machine (a 32-bit
/// xorshift; std::uniform_real_distribution may differ between libraries).
class SparkRandom {
public:
    explicit SparkRandom(std::uint32_t seed) : m_state(seed == 0u ? 1u : seed) {}
    /// Uniform in [0, 1).
    float next() {
        m_state ^= m_state << 13u;
        m_state ^= m_state >> 17u;
        m_state ^= m_state << 5u;
        return static_cast<float>(m_state >> 8u) / 16777216.0f;
    }

private:
    std::uint32_t m_state;
};

/// The sparks of one contact (given, not an exercise): settings.sparksPerContact
/// particles at the contact point, thrown into the half-space the normal points
/// to at random directions and speeds, with random lifetimes around sparkLifetime.
inline void spawnSparks(const Contact& contact, SparkRandom& random, const BounceSettings& settings,
                        std::vector<Particle>& particles) {
    for (int i = 0; i < settings.sparksPerContact; ++i) {
        // A random direction on the unit sphere, turned into the normal's half.
        const float z = 2.0f * random.next() - 1.0f;
        const float angle = 6.28318530718f * random.next();
        const float ring = std::sqrt(std::max(0.0f, 1.0f - z * z));
        glm::vec3 direction(ring * std::cos(angle), ring * std::sin(angle), z);
        if (glm::dot(direction, contact.normal) < 0.0f) direction = -direction;
        direction = glm::normalize(direction + contact.normal);   // leaning outwards
        Particle spark;
        spark.position = contact.point + 0.02f * contact.normal;
        spark.velocity = direction * contact.speed * settings.sparkSpeedScale * (0.3f + 0.7f * random.next());
        spark.lifetime = settings.sparkLifetime * (0.5f + random.next());
        particles.push_back(spark);
    }
}

/// What advanceSimulation() advances.
struct Simulation {
    Ball ball;
    std::vector<Particle> particles;
    BounceSettings settings;
    SparkRandom random{7u};
    float accumulator = 0.0f;   // frame time not yet simulated, in [0, settings.step)
    float time = 0.0f;          // simulated seconds: a whole number of steps
    int contacts = 0;           // contacts fast enough to throw sparks, so far
};

// --- bounce.cpp ---------------------------------------------------------

/// The point of `triangle` nearest to `point` (on its face, an edge or a corner).
glm::vec3 closestPointOnTriangle(const glm::vec3& point, const Triangle& triangle);

/// Appends to `out` the index (into bvh.triangles) of every triangle in a leaf
/// whose box overlaps the sphere's bounding box: a walk of the tree that skips
/// every node whose box does not overlap it.
void trianglesNearSphere(const Bvh& bvh, const BoundingSphere& sphere, std::vector<int>& out);

/// One fixed step of `seconds`: gravity changes the velocity, the velocity the
/// position (semi-implicit Euler); then, if the ball overlaps triangles, the one
/// whose closest point is nearest its centre pushes it out along the normal to
/// touching, and the velocity's part into the surface is reflected, scaled by
/// the restitution. Returns the contact when the ball was moving into the
/// surface, nothing otherwise.
std::optional<Contact> stepBall(Ball& ball, const Bvh& bvh, float seconds, const BounceSettings& settings);

/// Every particle: velocity += gravity * seconds, position += velocity * seconds,
/// age += seconds; then those with age >= lifetime are removed, the others keep
/// their order.
void stepParticles(std::vector<Particle>& particles, float seconds, const BounceSettings& settings);

/// Adds `frameSeconds` to the accumulator and runs whole fixed steps of
/// settings.step while it holds one (in each: stepBall(), sparks for a contact
/// faster than settings.sparkSpeed, stepParticles()), so that the result does
/// not depend on how the time was cut into frames.
void advanceSimulation(Simulation& simulation, const Bvh& bvh, float frameSeconds);

} // namespace stoa
