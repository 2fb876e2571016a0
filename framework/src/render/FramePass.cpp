#include <stoa/render/FramePass.hpp>

#include <stdexcept>

namespace stoa {

namespace {

constexpr FrameTarget kAll[] = {FrameTarget::Levels,      FrameTarget::CascadeMaps, FrameTarget::GBuffer,
                                FrameTarget::Occlusion,   FrameTarget::LightBuffer, FrameTarget::IdBuffer,
                                FrameTarget::Output};

} // namespace

const char* toString(FrameTarget target) {
    switch (target) {
    case FrameTarget::Levels: return "levels";
    case FrameTarget::CascadeMaps: return "cascade maps";
    case FrameTarget::GBuffer: return "G-buffer";
    case FrameTarget::Occlusion: return "occlusion";
    case FrameTarget::LightBuffer: return "light buffer";
    case FrameTarget::IdBuffer: return "id buffer";
    case FrameTarget::Output: return "output";
    }
    return "?";
}

std::string toString(FrameTargets targets) {
    std::string text;
    for (const FrameTarget target : kAll) {
        if (!targets.contains(target)) continue;
        if (!text.empty()) text += ", ";
        text += toString(target);
    }
    return text.empty() ? "-" : text;
}

void checkPassOrder(const std::vector<PassSignature>& passes, FrameTargets given) {
    FrameTargets written = given;
    for (const PassSignature& pass : passes) {
        const FrameTargets missing = pass.reads.without(written);
        if (!missing.empty())
            throw std::logic_error("the pass '" + pass.name + "' reads " + toString(missing) +
                                   ", which no earlier pass writes");
        written = written | pass.writes;
    }
}

} // namespace stoa
