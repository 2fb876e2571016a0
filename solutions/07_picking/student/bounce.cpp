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
    // Which feature of the triangle is nearest, from the signs of dot products
    // (the point's region among the corners', the edges' and the face's).
    const glm::vec3 a = triangle.p0, b = triangle.p1, c = triangle.p2;
    const glm::vec3 ab = b - a, ac = c - a, ap = point - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return a;                       // corner a
    const glm::vec3 bp = point - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return b;                         // corner b
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));   // edge ab
    const glm::vec3 cp = point - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return c;                         // corner c
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));   // edge ac
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)    // edge bc
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const float denominator = 1.0f / (va + vb + vc);                  // the face
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

void trianglesNearSphere(const Bvh& bvh, const BoundingSphere& sphere, std::vector<int>& out) {
    if (bvh.nodes.empty()) return;
    const glm::vec3 low = sphere.center - glm::vec3(sphere.radius);
    const glm::vec3 high = sphere.center + glm::vec3(sphere.radius);
    auto overlaps = [&](const Aabb& box) {
        return glm::all(glm::lessThanEqual(box.min, high)) && glm::all(glm::greaterThanEqual(box.max, low));
    };
    std::array<int, kMaxBvhDepth + 2> stack;
    int size = 0;
    if (overlaps(bvh.nodes[0].box)) stack[size++] = 0;
    while (size > 0) {
        const BvhNode& node = bvh.nodes[stack[--size]];
        if (node.count > 0) {
            for (int i = node.first; i < node.first + node.count; ++i) out.push_back(i);
            continue;
        }
        if (overlaps(bvh.nodes[node.first].box)) stack[size++] = node.first;
        if (overlaps(bvh.nodes[node.first + 1].box)) stack[size++] = node.first + 1;
    }
}

std::optional<Contact> stepBall(Ball& ball, const Bvh& bvh, float seconds, const BounceSettings& settings) {
    ball.velocity += settings.gravity * seconds;
    ball.position += ball.velocity * seconds;

    std::vector<int> near;
    trianglesNearSphere(bvh, {ball.position, ball.radius}, near);
    float nearestSquared = ball.radius * ball.radius;
    std::optional<glm::vec3> touched;
    for (int index : near) {
        const glm::vec3 point = closestPointOnTriangle(ball.position, bvh.triangles[index]);
        const glm::vec3 offset = ball.position - point;
        const float distanceSquared = glm::dot(offset, offset);
        if (distanceSquared < nearestSquared) {
            nearestSquared = distanceSquared;
            touched = point;
        }
    }
    if (!touched || nearestSquared <= 0.0f) return std::nullopt;   // no overlap (or the centre on a triangle: no normal)
    const glm::vec3 normal = (ball.position - *touched) / std::sqrt(nearestSquared);
    ball.position = *touched + normal * ball.radius;                  // just touching
    const float into = -glm::dot(ball.velocity, normal);
    if (into <= 0.0f) return std::nullopt;                            // already moving away
    ball.velocity += (1.0f + settings.restitution) * into * normal;   // reflect, keep restitution of it
    return Contact{*touched, normal, into};
}

void stepParticles(std::vector<Particle>& particles, float seconds, const BounceSettings& settings) {
    for (Particle& particle : particles) {
        particle.velocity += settings.gravity * seconds;
        particle.position += particle.velocity * seconds;
        particle.age += seconds;
    }
    particles.erase(std::remove_if(particles.begin(), particles.end(),
                                   [](const Particle& particle) { return particle.age >= particle.lifetime; }),
                    particles.end());
}

void advanceSimulation(Simulation& simulation, const Bvh& bvh, float frameSeconds) {
    simulation.accumulator += frameSeconds;
    const float step = simulation.settings.step;
    while (simulation.accumulator >= step) {
        const std::optional<Contact> contact = stepBall(simulation.ball, bvh, step, simulation.settings);
        if (contact && contact->speed > simulation.settings.sparkSpeed) {
            spawnSparks(*contact, simulation.random, simulation.settings, simulation.particles);
            ++simulation.contacts;
        }
        stepParticles(simulation.particles, step, simulation.settings);
        simulation.accumulator -= step;
        simulation.time += step;
    }
}

} // namespace stoa
