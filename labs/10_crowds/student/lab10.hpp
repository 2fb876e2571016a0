#pragma once
// Lab 10: everything you write (behaviour.cpp, ground.cpp, md2_blend.cpp). docs/labs/10_crowds.md
// derives each function. The lab's app, the tests and later labs include this header; your files
// define what it declares.

#include <stoa/crowd/CrowdLab.hpp>
#include <stoa/crowd/CrowdWorld.hpp>
#include <stoa/crowd/GroundMaps.hpp>
#include <stoa/geometry/Md2Model.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace stoa {

/// One step of a finite state machine for an agent in state `current`:
/// the transitions of `machine.states[current]` are tried in their order and
/// the first whose conditions all hold fires (an empty list always holds);
/// the agent is then in that transition's target state, or still in `current`
/// when none fires. `actions` is cleared and receives the actions of the
/// state the agent is in after the transition, in their order. Returns that state.
int stepStateMachine(const StateMachine& machine, int current, const CrowdSenses& senses,
                     std::vector<const Action*>& actions);

/// Subsumption: the index of the first layer of `stack` (the highest
/// priority) whose conditions all hold (a layer without conditions always
/// does); the layers below it are suppressed. -1 when none fires.
int arbitrateLayers(const SubsumptionStack& stack, const CrowdSenses& senses);

/// Whether the collision map lets an agent stand at `xz` (world x, z): the
/// texel that holds the point decides; points outside the footprint are not walkable.
bool walkableAt(const CollisionMap& map, glm::vec2 xz);

/// The ground's height at `xz` in metres: the field's values are samples at
/// the texel centres, read bilinearly between the four nearest (clamped to the
/// edge texels outside them), then mapped to [heightMin, heightMax].
float heightAt(const HeightField& field, glm::vec2 xz);

/// Where `seconds` falls in `animation` played at `framesPerSecond`, looping:
/// frame k of the animation is shown at k / framesPerSecond seconds, and after
/// its last frame it blends back into its first. Returned indices are into
/// the model's frames (animation.first + k).
Md2FramePair md2FramesAt(const Md2Animation& animation, float seconds, float framesPerSecond);

/// The pose between two key frames of the same model: positions linearly,
/// normals linearly and then normalized. `positions` and `normals` are resized.
void blendMd2Frames(const Md2Frame& first, const Md2Frame& second, float t, std::vector<glm::vec3>& positions,
                    std::vector<glm::vec3>& normals);

} // namespace stoa
