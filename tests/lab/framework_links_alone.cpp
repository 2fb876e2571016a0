// libstoa links alone: this program is linked with every object of the
// framework's archives (libstoa.a and libstoa_core.a, whole) and no lab code.
// Were any framework source to call a function a student writes other than
// through the student-code table (stoa/core/StudentCode.hpp), that function
// would be an undefined symbol here and the link would fail. Run, it checks the
// other half of the rule: an entry nobody handed over throws NotImplemented
// naming the function, as a stub does.

#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/core/StudentCode.hpp>

#include <cstdio>
#include <string>

int main() {
    const stoa::OrbitCamera camera({0.0f, 0.0f, 0.0f}, 3.0f, 0.0f, 0.0f);
    try {
        (void)camera.viewMatrix();
        std::fprintf(stderr, "FAIL: a view matrix without any student code\n");
        return 1;
    } catch (const stoa::NotImplemented& error) {
        // The eye comes first: eyePosition() is the first student function the view needs.
        if (error.function() != std::string("eyePosition(OrbitState)")) {
            std::fprintf(stderr, "FAIL: NotImplemented names '%s'\n", error.function().c_str());
            return 1;
        }
    }
    stoa::studentCode().cameras.eyePosition = [](const stoa::OrbitState& orbit) { return orbit.target; };
    try {
        (void)camera.viewMatrix();
        std::fprintf(stderr, "FAIL: lookAtMatrix() was never handed over, and yet it ran\n");
        return 1;
    } catch (const stoa::NotImplemented& error) {
        if (error.function() != std::string("lookAtMatrix()")) {
            std::fprintf(stderr, "FAIL: NotImplemented names '%s'\n", error.function().c_str());
            return 1;
        }
    }
    std::printf("the whole framework linked with no lab code; unset student functions throw NotImplemented\n");
    return 0;
}
