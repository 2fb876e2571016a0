#include "GlTestSupport.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/InputError.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/image/Image.hpp>

#include <cstdlib>

using namespace stoa;

TEST_CASE("HeadlessContext: an OpenGL 3.3 core context on llvmpipe") {
    HeadlessContext context;
    if (const char* chosen = std::getenv("STOA_HEADLESS"); chosen && *chosen)
        CHECK(std::string(toString(context.backend())) == chosen);
    INFO(context.description());
    CHECK(context.description().find("llvmpipe") != std::string::npos);

    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    CHECK(major * 10 + minor >= 33);
    CHECK((profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0);
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("HeadlessContext: OSMesa and EGL contexts one after another in one process") {
    const bool both = HeadlessContext::isAvailable(HeadlessBackend::OSMesa) &&
                      HeadlessContext::isAvailable(HeadlessBackend::Egl);
    int created = 0;
    for (HeadlessBackend backend : {HeadlessBackend::OSMesa, HeadlessBackend::Egl, HeadlessBackend::OSMesa}) {
        if (!HeadlessContext::isAvailable(backend)) {
            WARN(toString(backend) << " is not available here; skipped");
            continue;
        }
        HeadlessContext context(backend);
        CHECK(context.backend() == backend);
        // Each context draws for real: clear a framebuffer and read it back.
        Framebuffer target(4, 4);
        target.bind();
        glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        CHECK(target.readColor().pixel(2, 2) == glm::u8vec4(0, 255, 0, 255));
        ++created;
    }
    CHECK(created == (both ? 3 : 1)); // Mesa 25.1+ has no OSMesa: EGL alone then
}

TEST_CASE("HeadlessContext: backend names") {
    CHECK(std::string(toString(HeadlessBackend::OSMesa)) == "osmesa");
    CHECK(std::string(toString(HeadlessBackend::Egl)) == "egl");
    CHECK(parseHeadlessBackend("osmesa") == HeadlessBackend::OSMesa);
    CHECK(parseHeadlessBackend("egl") == HeadlessBackend::Egl);
    try {
        parseHeadlessBackend("glx");
        FAIL("parseHeadlessBackend(\"glx\") should throw");
    } catch (const InputError& error) {
        CHECK(error.file().empty());
        CHECK(error.message() == "unknown headless backend 'glx' (valid: osmesa, egl)");
    }
}

TEST_CASE("HeadlessContext: $STOA_HEADLESS chooses the backend and a wrong value is an InputError") {
    const char* saved = std::getenv("STOA_HEADLESS");
    const std::string previous = saved ? saved : "";

    setenv("STOA_HEADLESS", "egl", 1);
    CHECK(HeadlessContext::defaultBackend() == HeadlessBackend::Egl);
    setenv("STOA_HEADLESS", "vulkan", 1);
    CHECK_THROWS_AS(HeadlessContext(), InputError);
    try {
        HeadlessContext context;
    } catch (const InputError& error) {
        CHECK(error.message().find("STOA_HEADLESS") != std::string::npos);
        CHECK(error.message().find("'vulkan'") != std::string::npos);
    }

    if (saved) setenv("STOA_HEADLESS", previous.c_str(), 1);
    else unsetenv("STOA_HEADLESS");
}
