#include <stoa/core/Paths.hpp>

#include <cstdlib>

#ifndef STOA_SOURCE_DIR
#error "STOA_SOURCE_DIR must be defined by the build"
#endif

namespace stoa::paths {

std::filesystem::path sourceDir() {
    if (const char* overridden = std::getenv("STOA_SOURCE_DIR"); overridden && *overridden)
        return overridden;
    return STOA_SOURCE_DIR;
}

std::filesystem::path shadersDir() { return sourceDir() / "shaders"; }
std::filesystem::path assetsDir() { return sourceDir() / "assets"; }

} // namespace stoa::paths
