#include "Characters.hpp"

#include "CharacterRig.hpp"
#include "PortableMath.hpp"
#include "Writers.hpp"

#include <stoa/core/InputError.hpp>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <tuple>
#include <utility>

// A character is a rig: parts in a tree, each with a joint (its pivot, in its
// parent's space) and pieces of geometry around that joint. A pose gives each
// part a rotation (and a shift) about its joint; a frame is the rig's rest
// geometry carried through the posed tree, so every part moves rigidly. The
// rest geometry gives the MD2 file its triangles and texture coordinates;
// every animation frame only moves its vertices.

namespace stoa::assets {

namespace {

using namespace rig;


Md2Model buildModel(const Rig& rig, const std::vector<Animation>& animations, const std::string& skinName) {
    Md2Model model;
    model.skinWidth = kSkinSize;
    model.skinHeight = kSkinSize;
    model.skinNames = {skinName};
    // The rest geometry: one vertex and one texture coordinate per piece vertex.
    for (const Part& part : rig.parts) {
        for (const Piece& piece : part.pieces) {
            const int first = static_cast<int>(model.texCoords.size());
            const int island = static_cast<int>(piece.paint);
            const float x0 = static_cast<float>(island % 4 * kCell), y0 = static_cast<float>(island / 4 * kCell);
            for (const glm::vec2& uv : piece.uvs) {
                // Inside the island, 2 pixels from its edge (bilinear filtering stays on it), whole pixels.
                const float x = std::floor(x0 + 2.0f + uv.x * (kCell - 4) + 0.5f);
                const float y = std::floor(y0 + 2.0f + (1.0f - uv.y) * (kCell - 4) + 0.5f);
                model.texCoords.emplace_back(x / kSkinSize, 1.0f - y / kSkinSize);
            }
            for (const auto& triangle : piece.triangles) {
                Md2Triangle out;
                for (int corner = 0; corner < 3; ++corner) {
                    out.vertex[corner] = static_cast<std::uint16_t>(first + triangle[corner]);
                    out.texCoord[corner] = out.vertex[corner];
                }
                model.triangles.push_back(out);
            }
        }
    }
    for (const Animation& animation : animations) {
        for (int frame = 0; frame < animation.frames; ++frame) {
            // Pose is one Transform per part, identity unless the animation moves it.
            Pose pose(rig.parts.size());
            animation.pose(frame, pose);
            Md2Frame out;
            out.name = animation.name + std::to_string(frame + 1);
            std::vector<Transform> world(rig.parts.size());
            for (std::size_t i = 0; i < rig.parts.size(); ++i) {
                const Part& part = rig.parts[i];
                const Transform local = translate(part.joint) * pose[i];
                world[i] = part.parent < 0 ? local : world[static_cast<std::size_t>(part.parent)] * local;
                for (const Piece& piece : part.pieces) {
                    for (std::size_t v = 0; v < piece.positions.size(); ++v) {
                        out.positions.push_back(world[i].point(piece.positions[v]) * rig.scale);
                        out.normals.push_back(glm::normalize(world[i].direction(piece.normals[v])));
                    }
                }
            }
            float lowest = out.positions.front().y;
            for (const glm::vec3& p : out.positions) lowest = std::min(lowest, p.y);
            const float lift = animation.grounded ? -lowest : std::max(0.0f, -lowest);
            for (glm::vec3& p : out.positions) p.y += lift;
            model.frames.push_back(std::move(out));
        }
    }
    int first = 0;
    for (const Animation& animation : animations) {
        model.animations.push_back({animation.name, first, animation.frames});
        first += animation.frames;
    }
    return model;
}

// The explorer: a four-wheeled robot about 1.1 m tall. A chassis on four wheels,
// a mast with a sensor head (two cyan sensors, an antenna), and two arms that
// hold a sample box: folded forward over the chassis with the box between
// them, or raised in front of the chassis (carry).
struct Explorer {
    Rig rig;
    int chassis, mast, head, leftArm, rightArm;
    std::array<int, 4> wheels{};

    Explorer() {
        const int root = rig.add(-1, {0.0f, 0.0f, 0.0f}, {});
        chassis = rig.add(root, {0.0f, 0.32f, 0.0f},
                          {box({0.0f, 0.0f, 0.0f}, {0.56f, 0.2f, 0.7f}, Paint::Body),
                           box({0.0f, -0.12f, 0.0f}, {0.44f, 0.06f, 0.6f}, Paint::Dark),
                           box({0.0f, -0.04f, 0.365f}, {0.5f, 0.08f, 0.04f}, Paint::Dark)});
        int wheel = 0;
        for (const float x : {-0.33f, 0.33f}) {
            for (const float z : {-0.24f, 0.24f}) {
                // A cylinder along X, centred on the axle: 8 slices, the hub's cross on its caps.
                const Piece tire = moved(cylinder(0.1f, 0.16f, 0.16f, 8, Paint::Tire),
                                         rotateZ(radians(90.0)) * translate({0.0f, 0.05f, 0.0f}));
                wheels[static_cast<std::size_t>(wheel++)] = rig.add(root, {x, 0.16f, z}, {tire});
            }
        }
        mast = rig.add(chassis, {0.0f, 0.1f, -0.12f}, {box({0.0f, 0.15f, 0.0f}, {0.08f, 0.3f, 0.08f}, Paint::Leg)});
        head = rig.add(mast, {0.0f, 0.3f, 0.0f},
                       {box({0.0f, 0.09f, 0.0f}, {0.32f, 0.18f, 0.2f}, Paint::Body),
                        box({0.0f, 0.09f, 0.1f}, {0.26f, 0.08f, 0.02f}, Paint::Dark),
                        ellipsoid({-0.07f, 0.09f, 0.11f}, {0.035f, 0.035f, 0.02f}, 6, 4, Paint::Eye),
                        ellipsoid({0.07f, 0.09f, 0.11f}, {0.035f, 0.035f, 0.02f}, 6, 4, Paint::Eye),
                        box({0.12f, 0.25f, -0.05f}, {0.015f, 0.16f, 0.015f}, Paint::Leg),
                        ellipsoid({0.12f, 0.34f, -0.05f}, {0.025f, 0.025f, 0.025f}, 6, 4, Paint::Accent)});
        // The arms hang from their shoulders along -Y; the box is carried by the right one, centred between both.
        auto arm = [](float toBox) {
            std::vector<Piece> pieces{box({0.0f, -0.12f, 0.0f}, {0.05f, 0.26f, 0.05f}, Paint::Leg),
                                      box({0.0f, -0.24f, 0.0f}, {0.07f, 0.05f, 0.09f}, Paint::Dark)};
            if (toBox != 0.0f) pieces.push_back(box({toBox, -0.22f, 0.12f}, {0.3f, 0.2f, 0.2f}, Paint::Crate));
            return pieces;
        };
        leftArm = rig.add(chassis, {-0.2f, 0.12f, 0.0f}, arm(0.0f));
        rightArm = rig.add(chassis, {0.2f, 0.12f, 0.0f}, arm(-0.2f));
    }

    /// Folded arms (90 degrees forward) or raised ones, a head turned by `yaw`, the chassis bobbing by `bob`.
    void pose(Pose& pose, float armAngle, float yaw, float bob, float wheelTurn, float mastLean) const {
        pose[static_cast<std::size_t>(chassis)] = translate({0.0f, bob, 0.0f});
        pose[static_cast<std::size_t>(leftArm)] = swing(armAngle);
        pose[static_cast<std::size_t>(rightArm)] = swing(armAngle);
        pose[static_cast<std::size_t>(head)] = rotateY(yaw);
        pose[static_cast<std::size_t>(mast)] = rotateX(mastLean);
        for (const int wheel : wheels) pose[static_cast<std::size_t>(wheel)] = rotateX(wheelTurn);
    }

    std::vector<Animation> animations() const {
        // The wheels turn once per cycle, 45 degrees a frame, so that the last frame leads into the
        // first by the same step as any two neighbours (a blend between two frames shortens a spoke
        // to cos 22.5 = 92% of the radius at its middle: vertex animation cannot turn a wheel smoothly).
        auto run = [this](float armBase, float armSwing) {
            return [this, armBase, armSwing](int frame, Pose& p) {
                const double phase = cycle(frame, 8);
                pose(p, radians(armBase) + armSwing * sine(phase), 0.0f, 0.012f * sine(2.0 * phase),
                     static_cast<float>(2.0 * kPi * frame / 8), -0.06f + 0.03f * sine(2.0 * phase));
            };
        };
        return {{"stand", 4, true,
                 [this](int frame, Pose& p) {
                     const double phase = cycle(frame, 4);
                     pose(p, radians(90.0), 0.2f * sine(phase), 0.006f * sine(phase), 0.0f, 0.0f);
                 }},
                {"run", 8, true, run(90.0f, 0.03f)},
                {"carry", 8, true, run(130.0f, 0.05f)}};
    }
};

/// A quadruped's legs: hips at (+-x, hipHeight, front) and (+-x, hipHeight, back), each a
/// tapered cylinder down to a foot box whose sole is level with the hip's height below it.
struct Legs {
    std::array<int, 4> parts{};   // front left, front right, back left, back right

    void add(Rig& rig, int root, float x, float hipHeight, float front, float back, float top, float bottom,
             const glm::vec3& foot) {
        int i = 0;
        for (const float z : {front, back}) {
            for (const float side : {-x, x}) {
                parts[static_cast<std::size_t>(i++)] = rig.add(
                    root, {side, hipHeight, z},
                    {cylinder(hipHeight - foot.y, top, bottom, 6, Paint::Leg),
                     box({0.0f, -hipHeight + foot.y * 0.5f, foot.z * 0.2f}, foot, Paint::Dark)});
            }
        }
    }
    /// A trot: diagonal legs together, swinging `amplitude` radians about the hip.
    void trot(Pose& pose, double phase, float amplitude) const {
        const float a = amplitude * sine(phase);
        pose[static_cast<std::size_t>(parts[0])] = swing(a);
        pose[static_cast<std::size_t>(parts[3])] = swing(a);
        pose[static_cast<std::size_t>(parts[1])] = swing(-a);
        pose[static_cast<std::size_t>(parts[2])] = swing(-a);
    }
    void set(Pose& pose, float frontAngle, float backAngle) const {
        for (int i = 0; i < 4; ++i) pose[static_cast<std::size_t>(parts[static_cast<std::size_t>(i)])] = swing(i < 2 ? frontAngle : backAngle);
    }
};

// The predator: a wolf-like quadruped about 1.5 m from nose to tail and 0.9 m to
// its ears. Grey fur, darker legs and ears, a light belly and jaw, yellow eyes.
struct Predator {
    Rig rig;
    int root, torso, head, jaw, tail;
    Legs legs;

    Predator() {
        rig.scale = 0.85f;
        root = rig.add(-1, {0.0f, 0.0f, 0.0f}, {});
        torso = rig.add(root, {0.0f, 0.62f, 0.0f},
                        {ellipsoid({0.0f, 0.0f, -0.2f}, {0.15f, 0.17f, 0.35f}, 8, 6, Paint::Body),
                         ellipsoid({0.0f, 0.02f, 0.25f}, {0.17f, 0.2f, 0.28f}, 8, 6, Paint::Body),
                         ellipsoid({0.0f, -0.1f, 0.05f}, {0.12f, 0.09f, 0.35f}, 8, 4, Paint::Belly)});
        legs.add(rig, root, 0.11f, 0.56f, 0.36f, -0.38f, 0.055f, 0.035f, {0.08f, 0.05f, 0.12f});
        head = rig.add(torso, {0.0f, 0.12f, 0.45f},
                       {limb({0.0f, 0.0f, 0.0f}, rotateX(radians(-130.0)), 0.22f, 0.1f, 0.08f, 6, Paint::Body),
                        ellipsoid({0.0f, 0.17f, 0.22f}, {0.11f, 0.1f, 0.13f}, 8, 5, Paint::Body),
                        limb({0.0f, 0.16f, 0.3f}, rotateX(radians(-90.0)), 0.18f, 0.06f, 0.035f, 6, Paint::Body),
                        box({0.0f, 0.165f, 0.485f}, {0.045f, 0.035f, 0.03f}, Paint::Nose),
                        ellipsoid({-0.055f, 0.21f, 0.32f}, {0.022f, 0.018f, 0.015f}, 6, 4, Paint::Eye),
                        ellipsoid({0.055f, 0.21f, 0.32f}, {0.022f, 0.018f, 0.015f}, 6, 4, Paint::Eye),
                        limb({-0.06f, 0.24f, 0.19f}, rotateZ(radians(170.0)), 0.11f, 0.035f, 0.005f, 4, Paint::Dark),
                        limb({0.06f, 0.24f, 0.19f}, rotateZ(radians(-170.0)), 0.11f, 0.035f, 0.005f, 4, Paint::Dark)});
        jaw = rig.add(head, {0.0f, 0.11f, 0.3f}, {box({0.0f, 0.0f, 0.08f}, {0.07f, 0.03f, 0.16f}, Paint::Belly)});
        tail = rig.add(torso, {0.0f, 0.08f, -0.5f},
                       {limb({0.0f, 0.0f, 0.0f}, rotateX(radians(60.0)), 0.34f, 0.05f, 0.025f, 6, Paint::Body),
                        ellipsoid({0.0f, -0.17f, -0.3f}, {0.03f, 0.03f, 0.06f}, 6, 4, Paint::Dark)});
    }

    std::vector<Animation> animations() const {
        return {{"stand", 4, true,
                 [this](int frame, Pose& p) {
                     const double phase = cycle(frame, 4);
                     p[static_cast<std::size_t>(torso)] = translate({0.0f, 0.008f * sine(phase), 0.0f});
                     p[static_cast<std::size_t>(head)] = rotateX(0.04f * sine(phase + 1.0));
                     p[static_cast<std::size_t>(tail)] = rotateY(0.15f * sine(phase));
                 }},
                {"run", 8, true,
                 [this](int frame, Pose& p) {
                     const double phase = cycle(frame, 8);
                     legs.trot(p, phase, 0.55f);
                     p[static_cast<std::size_t>(torso)] = rotateX(0.03f * sine(2.0 * phase));
                     p[static_cast<std::size_t>(head)] = rotateX(0.12f + 0.06f * sine(2.0 * phase + 0.5));
                     p[static_cast<std::size_t>(tail)] = rotateX(-0.5f + 0.15f * sine(2.0 * phase));
                     p[static_cast<std::size_t>(jaw)] = rotateX(0.15f);
                 }},
                {"attack", 8, false,
                 // A pounce in place: crouch, spring up onto the hind legs, lunge and bite, shake, settle.
                 [this](int frame, Pose& p) {
                     struct Key { float rise, pitch, forward, front, back, jaw, shake; };
                     static const Key keys[8] = {
                         {-0.06f, 0.08f, 0.0f, 30.0f, -30.0f, 0.0f, 0.0f},  {-0.08f, 0.12f, -0.04f, 35.0f, -35.0f, 0.1f, 0.0f},
                         {0.12f, -0.35f, 0.1f, 70.0f, -20.0f, 0.4f, 0.0f},  {0.22f, -0.25f, 0.3f, 85.0f, -45.0f, 0.7f, 0.0f},
                         {0.12f, 0.1f, 0.45f, 60.0f, -50.0f, 0.75f, 0.0f},  {0.0f, 0.18f, 0.5f, 35.0f, -35.0f, 0.05f, 0.0f},
                         {0.0f, 0.12f, 0.4f, 25.0f, -25.0f, 0.05f, 0.35f},  {0.0f, 0.04f, 0.15f, 10.0f, -10.0f, 0.1f, -0.2f}};
                     const Key& key = keys[frame];
                     p[static_cast<std::size_t>(root)] = translate({0.0f, key.rise, key.forward}) * rotateX(key.pitch);
                     legs.set(p, radians(key.front), radians(key.back));
                     p[static_cast<std::size_t>(head)] = rotateX(-0.5f * key.pitch) * rotateY(key.shake);
                     p[static_cast<std::size_t>(jaw)] = rotateX(key.jaw);
                     p[static_cast<std::size_t>(tail)] = rotateX(-0.6f);
                 }}};
    }
};

// The prey: a deer-like quadruped about 1.3 m long and 1.3 m to its horns, on
// thin legs with dark hooves, a long neck, big ears, short ivory horns.
struct Prey {
    Rig rig;
    int root, torso, neck, head, tail;
    Legs legs;

    Prey() {
        root = rig.add(-1, {0.0f, 0.0f, 0.0f}, {});
        torso = rig.add(root, {0.0f, 0.7f, 0.0f},
                        {ellipsoid({0.0f, 0.0f, 0.0f}, {0.14f, 0.15f, 0.42f}, 8, 6, Paint::Body),
                         ellipsoid({0.0f, -0.06f, 0.0f}, {0.11f, 0.1f, 0.36f}, 8, 4, Paint::Belly)});
        legs.add(rig, root, 0.09f, 0.62f, 0.3f, -0.3f, 0.04f, 0.022f, {0.05f, 0.06f, 0.07f});
        neck = rig.add(torso, {0.0f, 0.06f, 0.34f},
                       {limb({0.0f, 0.0f, 0.0f}, rotateX(radians(-150.0)), 0.5f, 0.075f, 0.055f, 6, Paint::Body)});
        // The head sits at the neck's end (0.5 m along it): 0.5 * (0, cos 30, sin 30).
        head = rig.add(neck, {0.0f, 0.433f, 0.25f},
                       {ellipsoid({0.0f, 0.0f, 0.02f}, {0.075f, 0.075f, 0.1f}, 8, 5, Paint::Body),
                        limb({0.0f, -0.01f, 0.08f}, rotateX(radians(-70.0)), 0.14f, 0.05f, 0.03f, 6, Paint::Body),
                        box({0.0f, -0.058f, 0.215f}, {0.04f, 0.03f, 0.02f}, Paint::Nose),
                        ellipsoid({-0.058f, 0.03f, 0.07f}, {0.02f, 0.02f, 0.016f}, 6, 4, Paint::Eye),
                        ellipsoid({0.058f, 0.03f, 0.07f}, {0.02f, 0.02f, 0.016f}, 6, 4, Paint::Eye),
                        limb({-0.06f, 0.05f, -0.03f}, rotateZ(radians(125.0)), 0.13f, 0.035f, 0.01f, 4, Paint::Leg),
                        limb({0.06f, 0.05f, -0.03f}, rotateZ(radians(-125.0)), 0.13f, 0.035f, 0.01f, 4, Paint::Leg),
                        limb({-0.03f, 0.06f, 0.0f}, rotateZ(radians(-165.0)) * rotateX(radians(160.0)), 0.14f, 0.018f,
                             0.006f, 4, Paint::Accent),
                        limb({0.03f, 0.06f, 0.0f}, rotateZ(radians(165.0)) * rotateX(radians(160.0)), 0.14f, 0.018f,
                             0.006f, 4, Paint::Accent)});
        tail = rig.add(torso, {0.0f, 0.06f, -0.41f},
                       {limb({0.0f, 0.0f, 0.0f}, rotateX(radians(40.0)), 0.12f, 0.04f, 0.02f, 6, Paint::Belly)});
    }

    std::vector<Animation> animations() const {
        return {{"stand", 4, true,
                 [this](int frame, Pose& p) {
                     const double phase = cycle(frame, 4);
                     p[static_cast<std::size_t>(torso)] = translate({0.0f, 0.006f * sine(phase), 0.0f});
                     p[static_cast<std::size_t>(head)] = rotateY(0.25f * sine(phase));
                     p[static_cast<std::size_t>(tail)] = rotateX(0.3f * sine(2.0 * phase));
                 }},
                {"run", 8, true,
                 [this](int frame, Pose& p) {
                     const double phase = cycle(frame, 8);
                     legs.trot(p, phase, 0.5f);
                     p[static_cast<std::size_t>(torso)] = rotateX(0.03f * sine(2.0 * phase));
                     p[static_cast<std::size_t>(neck)] = rotateX(0.25f + 0.05f * sine(2.0 * phase));
                     p[static_cast<std::size_t>(tail)] = rotateX(-0.5f);
                 }},
                {"eat", 6, true,
                 // Head down to the grass, chewing, lifting it a little in the middle of the cycle.
                 [this](int frame, Pose& p) {
                     const double phase = cycle(frame, 6);
                     // Leaning forward a little on front legs set forward (the front feet stay level),
                     // the neck down to the grass and the head turned back so that the muzzle points down.
                     p[static_cast<std::size_t>(root)] = rotateX(0.08f);
                     legs.set(p, radians(15.0), radians(-5.0));
                     p[static_cast<std::size_t>(neck)] = rotateX(radians(125.0) - 0.06f * sine(phase));
                     p[static_cast<std::size_t>(head)] = rotateX(radians(-75.0) + 0.08f * sine(2.0 * phase));
                     p[static_cast<std::size_t>(tail)] = rotateX(0.2f * sine(2.0 * phase));
                 }}};
    }
};

struct Palette {
    std::array<glm::vec3, static_cast<std::size_t>(Paint::Count)> colors;   // sRGB, 0..255
};

/// A value in [0, 1) that looks random and is the same everywhere: an integer hash of (x, y, seed).
float grain(int x, int y, std::uint32_t seed) {
    std::uint32_t h = static_cast<std::uint32_t>(x) * 374761393u + static_cast<std::uint32_t>(y) * 668265263u + seed * 2246822519u;
    h = (h ^ (h >> 13)) * 1274126177u;
    h ^= h >> 16;
    return static_cast<float>(h & 0xFFFFu) / 65536.0f;
}

/// The skin: every island filled with its paint, a fine grain over all, and
/// each paint's own marks (dark edges on the robot's panels and the crate, a
/// hub cross on the tires, a highlight in the eyes, a darker back stripe on fur).
Image paintSkin(const Palette& palette, bool robot, std::uint32_t seed) {
    Image image(kSkinSize, kSkinSize, 3);
    for (int y = 0; y < kSkinSize; ++y) {
        for (int x = 0; x < kSkinSize; ++x) {
            const int island = y / kCell * 4 + x % kSkinSize / kCell;
            const Paint paint = island < static_cast<int>(Paint::Count) ? static_cast<Paint>(island) : Paint::Body;
            glm::vec3 color = palette.colors[static_cast<std::size_t>(paint)];
            // Position inside the island's painted square, 0..1 (the uvs' range).
            const float u = (static_cast<float>(x % kCell) + 0.5f - 2.0f) / (kCell - 4);
            const float v = 1.0f - (static_cast<float>(y % kCell) + 0.5f - 2.0f) / (kCell - 4);
            const float edge = std::min(std::min(u, 1.0f - u), std::min(v, 1.0f - v));
            if (paint == Paint::Crate && edge < 0.14f) color *= 0.45f;
            if (paint == Paint::Crate && std::abs(u - v) < 0.06f) color *= 0.7f;   // a brace across each face
            if (robot && paint == Paint::Body && edge < 0.05f) color *= 0.6f;
            if (paint == Paint::Tire && (std::abs(u - 0.5f) < 0.1f || std::abs(v - 0.5f) < 0.1f)) color = {165, 165, 172};
            if (paint == Paint::Eye && u > 0.55f && u < 0.75f && v > 0.6f && v < 0.8f) color = {250, 250, 245};
            if (!robot && paint == Paint::Body && v > 0.8f) color *= 0.75f;   // the top of each fur island: the back
            const float shade = robot ? 0.96f + 0.08f * grain(x, y, seed) : 0.86f + 0.22f * grain(x / 2, y, seed);
            color = glm::clamp(color * shade, glm::vec3(0.0f), glm::vec3(255.0f));
            std::uint8_t* pixel = image.data() + (static_cast<std::size_t>(y) * kSkinSize + static_cast<std::size_t>(x)) * 3;
            for (int channel = 0; channel < 3; ++channel) pixel[channel] = static_cast<std::uint8_t>(color[channel] + 0.5f);
        }
    }
    return image;
}

//                                 Body             Dark           Leg             Eye             Belly
//                                 Nose             Accent         Tire            Crate
const Palette kExplorerColors{{{{232, 182, 44}, {68, 70, 80}, {120, 122, 130}, {70, 225, 255}, {200, 200, 200},
                                {30, 30, 30}, {225, 45, 40}, {38, 38, 42}, {205, 112, 40}}}};
const Palette kPredatorColors{{{{128, 122, 116}, {64, 58, 54}, {92, 86, 80}, {245, 200, 40}, {196, 190, 178},
                                {22, 20, 20}, {128, 122, 116}, {38, 38, 42}, {128, 122, 116}}}};
const Palette kPreyColors{{{{170, 118, 66}, {46, 36, 30}, {118, 80, 48}, {30, 22, 18}, {236, 226, 206},
                            {40, 30, 26}, {226, 214, 184}, {38, 38, 42}, {170, 118, 66}}}};

void createFolder(const std::filesystem::path& folder) {
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) throw InputError(folder.string(), 0, "cannot create the output folder (" + error.message() + ")");
}

} // namespace

const std::vector<std::string>& characterFileNames() {
    static const std::vector<std::string> names{"explorer.md2", "explorer_skin.png", "predator.md2",
                                                "predator_skin.png", "prey.md2", "prey_skin.png"};
    return names;
}

Md2Model characterModel(const std::string& name) {
    const std::string skin = name + "_skin.png";
    if (name == "explorer") {
        const Explorer explorer;
        return buildModel(explorer.rig, explorer.animations(), skin);
    }
    if (name == "predator") {
        const Predator predator;
        return buildModel(predator.rig, predator.animations(), skin);
    }
    if (name == "prey") {
        const Prey prey;
        return buildModel(prey.rig, prey.animations(), skin);
    }
    throw std::invalid_argument("characterModel(): no character \"" + name + "\"; expected explorer, predator or prey");
}

Image characterSkin(const std::string& name) {
    if (name == "explorer") return paintSkin(kExplorerColors, true, 11u);
    if (name == "predator") return paintSkin(kPredatorColors, false, 23u);
    if (name == "prey") return paintSkin(kPreyColors, false, 37u);
    throw std::invalid_argument("characterSkin(): no character \"" + name + "\"; expected explorer, predator or prey");
}

void generateCharacters(const std::filesystem::path& folder) {
    createFolder(folder);
    for (const char* name : {"explorer", "predator", "prey"}) {
        writeText(folder / (std::string(name) + ".md2"), encodeMd2(characterModel(name)));
        writePng(folder / (std::string(name) + "_skin.png"), characterSkin(name));
    }
}

} // namespace stoa::assets
