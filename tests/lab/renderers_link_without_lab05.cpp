// Issue 10, item 4: the framework's renderers call later labs' code only
// through hooks handed over at run time (LabHooks, ShadowLabCode), so a program
// that uses them links without that code. This program links the framework
// and lab 01's student code alone (the matrices every renderer needs) and
// takes the address of the ShadowRenderer's and ForwardRenderer's entry points:
// if either named one of lab 05's functions, it would not link. It covers the
// course pipeline's renderer too: CourseRenderer takes labs 04-10's code
// through CourseLabCode, so naming any of it directly would fail the link here.

#include <stoa/render/CourseRenderer.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/render/ShadowRenderer.hpp>

#include <cstdio>

int main() {
    const auto shadow = &stoa::ShadowRenderer::render;
    const auto forward = &stoa::ForwardRenderer::render;
    const auto course = &stoa::CourseRenderer::render;
    std::printf("linked without lab 05: ShadowRenderer::render %s, ForwardRenderer::render %s, "
                "CourseRenderer::render %s\n",
                shadow ? "present" : "missing", forward ? "present" : "missing", course ? "present" : "missing");
    return shadow && forward && course ? 0 : 1;
}
