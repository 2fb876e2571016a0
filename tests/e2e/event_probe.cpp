// A lab that prints every window event and the first update step it gets, one
// line each ("event KeyUp a", "event MouseDown Right at 100,80", "update 0.0167"),
// and takes key H for itself (the app then leaves it alone):
// tests/e2e/window_events.sh drives it under Xvfb with xdotool. It is a Lab
// like any other, run by runLab(), so what it prints is what a lab receives.

#include <stoa/gl/RenderPass.hpp>
#include <stoa/lab/CameraRig.hpp>
#include <stoa/lab/CaseManifest.hpp>
#include <stoa/lab/LabApp.hpp>

#include <cstdio>

namespace {

class EventProbeLab : public stoa::Lab {
public:
    void initialize(stoa::LabResources&) override {}
    void loadCase(const stoa::CaseSpec& spec) override { m_cameras.loadCase(spec); }
    void render(glm::ivec2 size) override {
        stoa::PassDescription pass = stoa::passInto(size);
        pass.clear.color = pass.clear.depth = true;
        pass.clear.colorValue = {0.2f, 0.3f, 0.4f, 1.0f};
        stoa::beginPass(pass);
    }
    stoa::Camera& activeCamera() override { return m_cameras.active(); }

    bool handleEvent(const stoa::InputEvent& event) override {
        using Type = stoa::InputEvent::Type;
        std::printf("event %s", stoa::eventTypeName(event.type));
        switch (event.type) {
        case Type::KeyDown:
        case Type::KeyUp: std::printf(" %s", stoa::keyName(event.key)); break;
        case Type::Text: std::printf(" %c", static_cast<char>(event.character)); break;
        case Type::MouseDown:
        case Type::MouseUp: {
            static const char* const names[] = {"Left", "Middle", "Right"};
            std::printf(" %s at %d,%d", names[static_cast<int>(event.button)], static_cast<int>(event.position.x),
                        static_cast<int>(event.position.y));
            break;
        }
        case Type::MouseMove: std::printf(" %d,%d", static_cast<int>(event.position.x), static_cast<int>(event.position.y)); break;
        case Type::Wheel: std::printf(" %d", event.wheel); break;
        case Type::Resize: std::printf(" %dx%d", event.size.x, event.size.y); break;
        }
        if (event.modifiers.shift) std::printf(" +shift");
        if (event.modifiers.control) std::printf(" +control");
        if (event.modifiers.alt) std::printf(" +alt");
        std::printf("\n");
        std::fflush(stdout);
        // Only watching, but for H: the probe takes it, so the app must not
        // print its help again.
        return event.type == Type::KeyDown && event.key == stoa::keyOf('h');
    }

    void update(float seconds) override {
        if (m_steps++ == 0) {
            std::printf("update %.4f\n", seconds);
            std::fflush(stdout);
        }
    }

private:
    stoa::CameraRig m_cameras;
    int m_steps = 0;
};

} // namespace

int main(int argc, char** argv) {
    EventProbeLab lab;
    const stoa::LabBuildInfo info{"event_probe", "test", STOA_EVENT_PROBE_DIR, STOA_EVENT_PROBE_SHADERS};
    return stoa::runLab(lab, info, argc, argv);
}
