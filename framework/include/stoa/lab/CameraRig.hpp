#pragma once
// The two cameras of a lab app and which one is active. A graded case sets the
// pose from its manifest keys; the window's Tab key switches cameras.
//
// Case keys (all optional but `camera`):
//   camera = orbit | first_person
//   target = x y z        distance = d      yaw = degrees     pitch = degrees   (orbit)
//   position = x y z      yaw = degrees     pitch = degrees                     (first_person)
//   fov = degrees         near = n          far = f
//   input = tumble 30 -10; track 0.5 0; dolly 1     (orbit)
//   input = look 20 -5; move 1 0 2                  (first_person)
// `input` replays camera updates in order before the frame is drawn, so the
// cases grade the student's camera code and not only the matrices.

#include <stoa/camera/FirstPersonCamera.hpp>
#include <stoa/camera/OrbitCamera.hpp>

#include <string>

namespace stoa {

class CaseSpec;

class CameraRig {
public:
    OrbitCamera orbit{glm::vec3(0.0f), 6.0f, 30.0f, 20.0f};
    FirstPersonCamera firstPerson{glm::vec3(0.0f, 1.5f, 6.0f), 0.0f, 0.0f};

    Camera& active() { return m_orbitActive ? static_cast<Camera&>(orbit) : firstPerson; }
    const Camera& active() const { return m_orbitActive ? static_cast<const Camera&>(orbit) : firstPerson; }
    bool orbitActive() const { return m_orbitActive; }
    /// Switches cameras; the other one starts where the active one was.
    void toggle();

    /// Reads the keys above from `spec` (InputError on bad values, naming the manifest).
    void loadCase(const CaseSpec& spec);
    /// Runs an input script (syntax above) on the active camera; `file`/`line` locate it for errors.
    void applyInput(const std::string& script, const std::string& file, int line);

private:
    bool m_orbitActive = true;
};

} // namespace stoa
