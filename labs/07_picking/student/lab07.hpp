#pragma once
// Lab 07: everything you write, for ray casting and picking in rays.cpp and
// bvh.cpp (the ID buffer and the outline are id_buffer.glsl), and for the
// bouncing ball in bounce.cpp (part 4, below). The app (lab.cpp) and the tests
// include this header; docs/labs/07_picking.md explains the math.
//
// The app collects the Acropolis's triangles in world space, builds your BVH
// once (buildBvh), and casts one ray per pixel through it:
//   ray = rayThroughPixel(pixel centre, viewport, inverse(projection * view))
//   hit = intersectBvh(bvh, ray)          // which calls rayHitsBox, rayHitsTriangle

#include <stoa/geometry/Bounds.hpp>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace stoa {

/// A ray origin + t direction, t >= 0. inverseDirection is 1 / direction per
/// component (infinite where a component is 0), for the slab test; makeRay()
/// fills it.
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    glm::vec3 inverseDirection{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(), -1.0f};
};

/// The ray from `origin` along `direction` (need not be unit length: t is then in its units).
inline Ray makeRay(const glm::vec3& origin, const glm::vec3& direction) {
    return {origin, direction, glm::vec3(1.0f) / direction};
}

/// A triangle in world space, and the object it belongs to (an index into the
/// app's objects).
struct Triangle {
    glm::vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};
    int object = -1;
};

/// The nearest hit found so far: none while triangle < 0.
struct Hit {
    float t = std::numeric_limits<float>::infinity();
    int triangle = -1;   // index into Bvh::triangles
    float u = 0.0f;      // barycentric: the point is (1 - u - v) p0 + u p1 + v p2
    float v = 0.0f;
    bool found() const { return triangle >= 0; }
};

// --- rays.cpp -----------------------------------------------------------

/// The ray from the camera through `pixel` of a `viewport` (pixels from the
/// top-left corner, x right, y down; a pixel's centre is at + 0.5), given the
/// inverse of projection * view: it starts on the near plane and points to the
/// same pixel on the far plane, direction of unit length.
Ray rayThroughPixel(const glm::vec2& pixel, const glm::ivec2& viewport, const glm::mat4& inverseViewProjection);

/// The slab test: true when the ray meets `box` at some t in [0, tMax]; then
/// `tEntry` is where it enters (0 when the origin is inside).
bool rayHitsBox(const Ray& ray, const Aabb& box, float tMax, float& tEntry);

/// Moller and Trumbore (1997): true when the ray meets `triangle` (either side)
/// at a t in (epsilon, hit.t); then hit.t, hit.u and hit.v are set (not
/// hit.triangle: the caller knows which triangle it tested).
bool rayHitsTriangle(const Ray& ray, const Triangle& triangle, Hit& hit);

// --- bvh.cpp ------------------------------------------------------------

/// A node of the tree. A leaf (count > 0) holds triangles first .. first +
/// count - 1 of Bvh::triangles; an inner node (count == 0) has its two
/// children at nodes[first] and nodes[first + 1].
struct BvhNode {
    Aabb box;
    int first = 0;
    int count = 0;
};

/// The deepest a tree may grow (the root is depth 0): the builder makes a node
/// at this depth a leaf, so that a traversal stack of kMaxBvhDepth + 2 entries
/// always suffices.
constexpr int kMaxBvhDepth = 60;

struct Bvh {
    std::vector<Triangle> triangles;   // reordered by the build: each leaf's are contiguous
    std::vector<BvhNode> nodes;        // nodes[0] is the root
};

struct BvhSettings {
    int bins = 12;                 // candidate split planes per axis: bins - 1
    int maxLeafSize = 4;           // a node with more triangles is always split (when it can be)
    float traversalCost = 1.0f;    // C_t: visiting a node
    float intersectionCost = 1.0f; // C_i: testing a triangle
};

/// The surface area heuristic's cost of splitting a node of surface area
/// `parentArea` into children of areas and triangle counts (leftArea,
/// leftCount) and (rightArea, rightCount):
/// C_t + C_i (leftArea leftCount + rightArea rightCount) / parentArea.
float sahSplitCost(float leftArea, int leftCount, float rightArea, int rightCount, float parentArea,
                   const BvhSettings& settings);

/// Builds the tree over `triangles` top-down with binned SAH splits along
/// the triangles' centroids. Every triangle ends up in exactly one leaf.
Bvh buildBvh(std::vector<Triangle> triangles, const BvhSettings& settings = {});

/// The nearest hit of `ray` among the tree's triangles (hit.triangle indexes
/// bvh.triangles), visiting the nearer child first and skipping every node that
/// the ray enters beyond the nearest hit so far.
Hit intersectBvh(const Bvh& bvh, const Ray& ray);

/// The surface area of a box (0 for an empty or inverted one).
inline float surfaceArea(const Aabb& box) {
    const glm::vec3 size = box.max - box.min;
    if (size.x < 0.0f || size.y < 0.0f || size.z < 0.0f) return 0.0f;
    return 2.0f * (size.x * size.y + size.y * size.z + size.z * size.x);
}

// --- Part 4, bounce.cpp: a bouncing ball and its sparks --------------------
// A ball that falls through the Acropolis, bounces off the triangles your BVH
// finds near it, and throws sparks where it hits (the sparks' billboards are
// particles.glsl); docs/labs/07_picking.md, "A bouncing ball", explains the physics.
//
// Every frame the app calls advanceSimulation(simulation, bvh, frameSeconds),
// which runs as many fixed steps of simulation.settings.step as the frames
// have added up to, each one:
//   contact = stepBall(ball, bvh, step, settings)   // trianglesNearSphere, closestPointOnTriangle
//   if (contact && contact->speed > settings.sparkSpeed) spawnSparks(*contact, random, settings, particles)
//   stepParticles(particles, step, settings)

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
