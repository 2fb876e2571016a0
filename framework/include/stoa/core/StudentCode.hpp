#pragma once
// The one way student code reaches the framework: a table of the functions
// students write that the framework calls, grouped by concept. The framework
// names no lab and links no student code; a lab program fills the entries of
// the labs it links at start-up (each lab's hand_over.cpp, called by runLab()),
// and a test fills them with doubles (StudentCodeScope). An entry left unset
// throws NotImplemented with the function's name when the framework calls it;
// a pass that is optional (culling, cascades) asks whether it is set first.
//
//   studentCode().transforms.lookAtMatrix = &stoa::lookAtMatrix;   // a hand-over
//   glm::mat4 view = studentCode().transforms.lookAtMatrix(eye, target, up);
//
// The functions themselves are declared, with what each must do, in the
// header of the lab that writes them, in the lab's student/ folder
// (labs/01_transforms/student/lab01.hpp for lab 01).

#include <stoa/core/StudentFunction.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace stoa {

struct Action;
struct BoundingSphere;
class Camera;
struct CollisionMap;
class CrowdSenses;
struct DepthRange;
struct FirstPersonState;
class Framebuffer;
struct HeightField;
struct LightSphere;
struct Md2Animation;
struct Md2Frame;
struct Md2FramePair;
struct OrbitState;
struct PointLight;
class Program;
struct RenderState;
class Scene;
struct StateMachine;
struct SubsumptionStack;
struct TileGrid;
struct TileLightLists;

/// The three matrices: every Object's model matrix, every Camera's view and projection.
struct TransformFunctions {
    StudentFunction<glm::mat4(const glm::vec3& position, const glm::vec3& rotationDegrees, const glm::vec3& scale)>
        modelMatrix{"modelMatrix()"};
    StudentFunction<glm::mat4(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up)> lookAtMatrix{
        "lookAtMatrix()"};
    StudentFunction<glm::mat4(float fovYDegrees, float aspect, float near, float far)> perspectiveMatrix{
        "perspectiveMatrix()"};
};

/// What the orbit and first-person cameras do with the mouse and keys.
struct CameraFunctions {
    StudentFunction<glm::vec3(const OrbitState& orbit)> eyePosition{"eyePosition(OrbitState)"};
    StudentFunction<void(OrbitState& orbit, float deltaYawDegrees, float deltaPitchDegrees)> tumble{
        "tumble(OrbitState)"};
    StudentFunction<void(OrbitState& orbit, float right, float up)> track{"track(OrbitState)"};
    StudentFunction<void(OrbitState& orbit, float amount)> dolly{"dolly(OrbitState)"};
    StudentFunction<glm::vec3(const FirstPersonState& view)> forward{"forward(FirstPersonState)"};
    StudentFunction<void(FirstPersonState& view, float deltaYawDegrees, float deltaPitchDegrees)> look{
        "look(FirstPersonState)"};
    StudentFunction<void(FirstPersonState& view, const glm::vec3& amount)> move{"move(FirstPersonState)"};
};

/// Shadow maps: the depth pass and the cascades' split, slices and light matrices.
struct ShadowFunctions {
    StudentFunction<void(const Scene& scene, const Framebuffer& shadowMap, const Program& depthProgram,
                         const glm::mat4& lightSpaceMatrix)>
        renderShadowPass{"renderShadowPass()"};
    StudentFunction<std::vector<float>(float near, float far, int count, float lambda)> cascadeSplits{
        "cascadeSplits()"};
    StudentFunction<std::array<glm::vec3, 8>(const glm::mat4& viewMatrix, float fovYDegrees, float aspect,
                                             float sliceNear, float sliceFar)>
        frustumSliceCorners{"frustumSliceCorners()"};
    StudentFunction<glm::mat4(const glm::vec3& lightDirection, const std::array<glm::vec3, 8>& sliceCornersWorld,
                              int mapSize, const glm::vec3& sceneMin, const glm::vec3& sceneMax)>
        cascadeLightMatrix{"cascadeLightMatrix()"};
};

/// Visibility and level of detail, as a renderer asks for them.
struct CullingFunctions {
    /// False when `sphere` (world) lies outside what `viewProjection` (world -> clip) sees.
    StudentFunction<bool(const BoundingSphere& sphere, const glm::mat4& viewProjection)> isVisible{
        "sphereInFrustum()"};
    /// The level to draw out of `levelCount` (0 the full mesh), -1 for too small to draw.
    StudentFunction<int(const BoundingSphere& sphere, const Camera& camera, int viewportHeight, int levelCount)>
        levelOf{"levelOfDetail()"};
};

/// Deferred shading's lights: their reach, the light volumes' state, the tiles' lists.
struct DeferredFunctions {
    StudentFunction<float(const PointLight& light, float cutoff)> lightReach{"lightReach()"};
    StudentFunction<RenderState()> lightVolumeState{"lightVolumeState()"};
    StudentFunction<TileLightLists(const std::vector<LightSphere>& lights, const glm::mat4& projection, float near,
                                   const TileGrid& grid, const std::vector<DepthRange>& depthRanges)>
        buildTileLightLists{"buildTileLightLists()"};
};

/// Screen-space ambient occlusion's samples.
struct OcclusionFunctions {
    StudentFunction<std::vector<glm::vec3>(int size, std::uint32_t seed)> ssaoKernel{"ssaoKernel()"};
    StudentFunction<std::vector<glm::vec3>(std::uint32_t seed)> ssaoNoise{"ssaoNoise()"};
};

/// What the crowd simulation and its renderer ask of the agents' behaviour,
/// the ground and the MD2 animation.
struct CrowdFunctions {
    StudentFunction<int(const StateMachine& machine, int current, const CrowdSenses& senses,
                        std::vector<const Action*>& actions)>
        stepStateMachine{"stepStateMachine()"};
    StudentFunction<int(const SubsumptionStack& stack, const CrowdSenses& senses)> arbitrateLayers{
        "arbitrateLayers()"};
    StudentFunction<bool(const CollisionMap& map, glm::vec2 xz)> walkableAt{"walkableAt()"};
    StudentFunction<float(const HeightField& field, glm::vec2 xz)> heightAt{"heightAt()"};
    StudentFunction<Md2FramePair(const Md2Animation& animation, float seconds, float framesPerSecond)> md2FramesAt{
        "md2FramesAt()"};
    StudentFunction<void(const Md2Frame& first, const Md2Frame& second, float t, std::vector<glm::vec3>& positions,
                         std::vector<glm::vec3>& normals)>
        blendMd2Frames{"blendMd2Frames()"};
};

struct StudentCode {
    TransformFunctions transforms;
    CameraFunctions cameras;
    ShadowFunctions shadows;
    CullingFunctions culling;
    DeferredFunctions deferred;
    OcclusionFunctions occlusion;
    CrowdFunctions crowds;
};

/// The process's table: filled at start-up, read by the framework.
StudentCode& studentCode();

/// For tests: keeps the table as it was and puts it back when the scope ends,
/// so that a test's doubles do not outlive it.
class StudentCodeScope {
public:
    StudentCodeScope() : m_saved(studentCode()) {}
    ~StudentCodeScope() { studentCode() = m_saved; }
    StudentCodeScope(const StudentCodeScope&) = delete;
    StudentCodeScope& operator=(const StudentCodeScope&) = delete;

private:
    StudentCode m_saved;
};

} // namespace stoa
