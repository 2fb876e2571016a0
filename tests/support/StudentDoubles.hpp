#pragma once
// Test doubles for the student functions the framework calls (StudentCode.hpp),
// so that the framework's tests link no lab code. They are written with glm's
// own functions (glm::lookAt, glm::perspective, glm::rotate ...), independently
// of the solutions, and only as far as the framework's tests need them.

namespace stoa {
struct StudentCode;
}

namespace doubles {

/// Fills the transforms (model, view, projection) and the cameras' functions.
void handOverTransformsAndCameras(stoa::StudentCode& code);

} // namespace doubles
