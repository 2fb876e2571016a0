#pragma once
// Test doubles for the student functions the framework calls (StudentCode.hpp),
// so that the framework's tests link no lab code: the three matrices, made by
// glm's own functions (glm::translate, glm::rotate, glm::scale, glm::lookAt,
// glm::perspective), which lab 01's page names as what students reimplement.
// Only these: the student release ships this file, so it holds no answer a
// lab asks for (the framework's tests use cameras that need no lab code).

namespace stoa {
struct StudentCode;
}

namespace doubles {

/// Fills the transforms: model, view and projection matrices.
void handOverTransforms(stoa::StudentCode& code);

} // namespace doubles
