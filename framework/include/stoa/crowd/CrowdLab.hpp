#pragma once
// The types lab 10's functions work with: what an agent senses and a pair of
// key frames. The functions themselves are the student's, declared in lab 10's
// header (labs/10_crowds/student/lab10.hpp; docs/labs/10_crowds.md explains each one):
//
//   behaviour.cpp   stepStateMachine   one step of a finite state machine
//                   arbitrateLayers    which subsumption layer runs
//   ground.cpp      walkableAt         the collision map at a point (x, z)
//                   heightAt           the height map at a point, bilinear
//   md2_blend.cpp   md2FramesAt        which two key frames a time falls between
//                   blendMd2Frames     the pose between them
//
// CrowdSimulation and CrowdRenderer reach them through the framework's
// student-code table (StudentCode::crowds), so a program that does not draw
// crowds never needs lab 10's code.

#include <stoa/crowd/CrowdWorld.hpp>
#include <stoa/crowd/GroundMaps.hpp>
#include <stoa/geometry/Md2Model.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace stoa {

/// What an agent senses this step: the simulation's answer to a Condition,
/// `negated` already applied (a <not> test is true when the test fails).
class CrowdSenses {
public:
    virtual ~CrowdSenses() = default;
    virtual bool holds(const Condition& condition) const = 0;
};

/// Two key frames and how far between them: the pose is
/// mix(frame[first], frame[second], t), t in [0, 1).
struct Md2FramePair {
    int first = 0;
    int second = 0;
    float t = 0.0f;
};

} // namespace stoa
