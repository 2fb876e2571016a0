#pragma once
// Where the source tree lives. Baked in at configure time so that a program in
// build/bin finds shaders/, assets/ and the lab manifests without arguments;
// STOA_SOURCE_DIR in the environment overrides it (for a moved tree).

#include <filesystem>

namespace stoa::paths {

std::filesystem::path sourceDir();   // the repository root
std::filesystem::path shadersDir();  // sourceDir()/shaders
std::filesystem::path assetsDir();   // sourceDir()/assets

} // namespace stoa::paths
