#pragma once
// CourseRenderer's passes (stoa/render/CourseRenderer.hpp), each an object that
// says what it reads and writes of the frame's shared targets
// (stoa/render/FramePass.hpp). The renderer runs them in order over one
// CourseFrame; a pass that is off for this frame (no shadows, a debug view that
// stops at the G-buffer) is skipped.

#include <stoa/render/AmbientOcclusionPass.hpp>
#include <stoa/render/CourseRenderer.hpp>
#include <stoa/render/DeferredRenderer.hpp>
#include <stoa/render/FramePass.hpp>
#include <stoa/render/ShadowCascades.hpp>
#include <stoa/render/TextureOverlay.hpp>

#include <glm/mat4x4.hpp>

#include <memory>
#include <string>
#include <vector>

namespace stoa {

/// The targets every pass shares, owned by the renderer for its lifetime.
struct CourseTargets {
    explicit CourseTargets(const CoursePrograms& programs);
    DeferredRenderer deferred;          // the G-buffer, the light buffer and the point lights' passes
    AmbientOcclusionPass occlusion;
    ShadowCascades cascades;
    TextureOverlay overlay;
    std::vector<int> levels;            // FrameTarget::Levels: -2 culled, -1 too small, else the level
    std::string occlusionStub;          // the lab 09 function still a stub ("" : none): no occlusion
};

/// One frame: what the caller gave and what the passes share.
struct CourseFrame {
    const std::vector<CourseItem>& items;
    const CourseLighting& lighting;
    const Camera& camera;
    glm::ivec2 size;
    const CourseSettings& settings;
    const CourseCrowd* crowd;                 // nullptr: no crowd
    const CourseRenderer::GlowPass& glow;     // empty: nothing glows
    unsigned output;                          // the framebuffer bound when the frame began
    glm::mat4 view;                           // the camera's
    CourseTargets& targets;
    CourseStats& stats;
    DeferredSettings deferred;                // the point lights' (the occlusion pass adds its picture)
    SceneLighting sceneLighting;              // the ambient light and the sky for the deferred passes
    bool cullingStubbed = false;              // lab 06's functions are stubs: nothing culled, full detail

    bool hasCrowd() const { return crowd && crowd->simulation && crowd->renderer; }
    /// The picture is lit: not one of the G-buffer's own views.
    bool lit() const { return deferred.view == DeferredView::Final; }
};

class CourseFramePass {
public:
    virtual ~CourseFramePass() = default;
    virtual PassSignature signature() const = 0;
    /// Which of CourseStats::seconds its time counts in.
    virtual CoursePass stage() const = 0;
    virtual bool enabled(const CourseFrame&) const { return true; }
    virtual void run(CourseFrame& frame) = 0;
};

/// The course's passes, in the order they run.
std::vector<std::unique_ptr<CourseFramePass>> makeCoursePasses(const CoursePrograms& programs);

} // namespace stoa
