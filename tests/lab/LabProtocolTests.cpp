// The lines a lab program prints for the grader: each one the lab writes, the
// grader reads back (LabProtocol.hpp).

#include "catch.hpp"

#include <stoa/core/NotImplemented.hpp>
#include <stoa/lab/LabProtocol.hpp>

#include <string>

using stoa::CheckVerdict;
using stoa::checkVerdictLine;
using stoa::notImplementedLine;
using stoa::notImplementedText;
using stoa::parseCheckVerdictLine;
using stoa::parseNotImplementedLine;

TEST_CASE("LabProtocol: the not-implemented line reads back what was not implemented") {
    for (const std::string what : {"Camera::viewMatrix()", "shadowFactor (05_shadows/student/shadows.glsl:12)", "a: b: c"}) {
        INFO(what);
        CHECK(notImplementedLine(what) == "stoa: not implemented: " + what);
        CHECK(parseNotImplementedLine(notImplementedLine(what)) == what);
        // The window and the check lines show the text without the program's prefix; it reads back too.
        CHECK(parseNotImplementedLine(notImplementedText(what)) == what);
    }
    CHECK_FALSE(parseNotImplementedLine("lab01: cases.ini:4: unknown key 'yaww'"));
    CHECK_FALSE(parseNotImplementedLine("stoa: not implemented: "));
}

TEST_CASE("LabProtocol: a check's verdict line reads back its name, verdict and message") {
    for (CheckVerdict verdict : {CheckVerdict::Holds, CheckVerdict::DoesNotHold, CheckVerdict::NotAttempted}) {
        const std::string line = checkVerdictLine("camera_limits", verdict, "pitch stops at 89: degrees: yes");
        const auto parsed = parseCheckVerdictLine(line);
        REQUIRE(parsed);
        CHECK(parsed->name == "camera_limits");
        CHECK(parsed->verdict == verdict);
        CHECK(parsed->message == "pitch stops at 89: degrees: yes");
    }
    CHECK(checkVerdictLine("slice_corners", CheckVerdict::DoesNotHold, "off by 0.5") ==
          "check slice_corners: does not hold: off by 0.5");
    CHECK_FALSE(parseCheckVerdictLine("check slice_corners: maybe: off"));
    CHECK_FALSE(parseCheckVerdictLine("2 of 3 checks hold"));
    CHECK_FALSE(parseCheckVerdictLine("check : holds: x"));
}

TEST_CASE("A stub names its lab only in another lab's program", "[lab][protocol]") {
    const stoa::NotImplemented own("meshBoundingSphere()", "06_culling");
    CHECK(own.describe("06_culling") == "meshBoundingSphere()");
    const stoa::NotImplemented earlier("FirstPersonCamera::forward()", "01_transforms");
    CHECK(earlier.describe("06_culling") == "FirstPersonCamera::forward() (lab 01_transforms)");
    const stoa::NotImplemented framework("something()", "");
    CHECK(framework.describe("06_culling") == "something()");
    // Thrown outside a lab's student files, the lab is empty (STOA_STUDENT_LAB is not defined here).
    CHECK(stoa::NotImplemented("f()").lab().empty());
}
