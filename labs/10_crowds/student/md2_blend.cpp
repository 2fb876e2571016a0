// Lab 10, part 3: animating MD2 characters between their key frames. Read
// docs/labs/10_crowds.md, "Key-frame animation", first.

#include "lab10.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/crowd/CrowdLab.hpp>

#include <glm/geometric.hpp>

#include <cmath>

namespace stoa {

Md2FramePair md2FramesAt(const Md2Animation& animation, float seconds, float framesPerSecond) {
    // TODO(lab10): how many frames have passed (seconds * framesPerSecond),
    // wrapped into one loop of animation.count frames; the whole part picks the
    // first frame, the fraction is t, and the second frame is the next one,
    // which after the animation's last frame is its first again. Indices are
    // animation.first + k (docs: "Key-frame animation").
    (void)animation;
    (void)seconds;
    (void)framesPerSecond;
    throw NotImplemented("md2FramesAt()");
}

void blendMd2Frames(const Md2Frame& first, const Md2Frame& second, float t, std::vector<glm::vec3>& positions,
                    std::vector<glm::vec3>& normals) {
    // TODO(lab10): for every vertex, mix the two positions and the two
    // normals by t; a blend of two unit normals is shorter than one, so
    // normalize it (docs: "Blending two frames").
    (void)first;
    (void)second;
    (void)t;
    (void)positions;
    (void)normals;
    throw NotImplemented("blendMd2Frames()");
}

} // namespace stoa
