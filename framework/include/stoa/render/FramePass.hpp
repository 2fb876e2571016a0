#pragma once
// What the passes of a frame read and write, so that a renderer made of passes
// can say so and check its order. A pass names the frame's shared targets it
// samples or depth-tests against (reads) and those it draws into (writes);
// checkPassOrder() refuses a list in which a pass reads a target that no
// earlier pass wrote. CourseRenderer::passes() lists its passes this way, and
// docs/framework.md ("Renderers made of passes") has the table.
//
//   checkPassOrder({{"g-buffer", FrameTarget::Levels, FrameTarget::GBuffer},
//                   {"occlusion", FrameTarget::GBuffer, FrameTarget::Occlusion}},
//                  FrameTarget::Levels);   // fine: Levels is given

#include <string>
#include <vector>

namespace stoa {

/// The targets the passes of a frame share.
enum class FrameTarget : unsigned {
    Levels = 1u << 0,        // each item's verdict: culled, too small, or its level of detail
    CascadeMaps = 1u << 1,   // the sun's shadow maps, one per cascade, and their matrices
    GBuffer = 1u << 2,       // albedo and specular, packed normal, depth and stencil
    Occlusion = 1u << 3,     // the blurred ambient occlusion, one value per pixel
    LightBuffer = 1u << 4,   // the HDR light buffer, with a copy of the G-buffer's depth
    IdBuffer = 1u << 5,      // each pixel's object id (lab 07)
    Output = 1u << 6,        // the framebuffer bound when the frame began
};

/// A set of targets.
class FrameTargets {
public:
    constexpr FrameTargets() = default;
    constexpr FrameTargets(FrameTarget target) : m_bits(static_cast<unsigned>(target)) {}   // NOLINT: a set of one
    constexpr FrameTargets operator|(FrameTargets other) const { return FrameTargets(m_bits | other.m_bits); }
    constexpr bool contains(FrameTarget target) const { return (m_bits & static_cast<unsigned>(target)) != 0; }
    constexpr bool containsAll(FrameTargets other) const { return (m_bits & other.m_bits) == other.m_bits; }
    constexpr bool empty() const { return m_bits == 0; }
    constexpr bool operator==(FrameTargets other) const { return m_bits == other.m_bits; }
    constexpr bool operator!=(FrameTargets other) const { return m_bits != other.m_bits; }
    /// The targets in `this` that are not in `other`.
    constexpr FrameTargets without(FrameTargets other) const { return FrameTargets(m_bits & ~other.m_bits); }

private:
    constexpr explicit FrameTargets(unsigned bits) : m_bits(bits) {}
    unsigned m_bits = 0;
};

constexpr FrameTargets operator|(FrameTarget a, FrameTarget b) { return FrameTargets(a) | FrameTargets(b); }

/// "levels", "cascade maps", "G-buffer", "occlusion", "light buffer", "id buffer", "output".
const char* toString(FrameTarget target);
/// The targets' names joined with ", " in the enum's order; "-" for none.
std::string toString(FrameTargets targets);

/// One pass of a frame, as its renderer describes it.
struct PassSignature {
    std::string name;
    FrameTargets reads;
    FrameTargets writes;
};

/// Throws std::logic_error naming the first pass that reads a target neither
/// `given` (what the frame starts with) nor an earlier pass wrote.
void checkPassOrder(const std::vector<PassSignature>& passes, FrameTargets given = {});

} // namespace stoa
