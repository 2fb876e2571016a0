#pragma once
// The files a lab program may touch while it renders a case (FileSandbox.hpp
// enforces them). It may read:
//   - the system (systemFileAccess()) and the Stoa tree's shaders/, assets/,
//     labs/ and autograder/references/ (what the student release holds too);
//   - its own build (the folder with the CMakeCache.txt above the program: its
//     student files, overlays and generated sources), without the work folder;
//   - the manifest its case comes from (--cases), and the suppressions
//     files its sanitizer runtime is told to read (ASAN_OPTIONS and the like);
//   - solutions/ only when the program was built from it (a solutions build:
//     references, planted mistakes); a student's cascade program (Cascade.hpp)
//     reads the shader files of the earlier labs' solutions it is graded with.
// It may write its case folder and the shader cache of the run (Mesa's, which
// makes the next case's shaders free), nothing else: not the submissions, the
// grades, another case or another student.

#include "CaseRunner.hpp"

#include <filesystem>

namespace stoa::grader {

/// What every lab program of a run may read, the work folder carved out; the
/// jobs add their own grants (labProgramAccess()).
FileAccess labProgramBaseAccess(const std::filesystem::path& sourceDir, const std::filesystem::path& workRoot);

/// The files of `job`'s program: settings.files, its build, its case folder and
/// the shader cache to write, and what its track needs (see above). Unconfined
/// when settings.files is.
FileAccess labProgramAccess(const CaseJob& job, const RunSettings& settings);

/// The build folder a program belongs to: the nearest folder above it with a
/// CMakeCache.txt, else the program's own folder.
std::filesystem::path buildRootOf(const std::filesystem::path& program);

/// True when the build in `buildRoot` compiled the solutions as its main track
/// (its CMakeCache.txt says STOA_USE_SOLUTIONS:BOOL=ON).
bool builtFromSolutions(const std::filesystem::path& buildRoot);

/// The folder the lab programs get as MESA_SHADER_CACHE_DIR by default: this
/// user's Mesa cache folder ($MESA_SHADER_CACHE_DIR, $XDG_CACHE_HOME/mesa_shader_cache
/// or ~/.cache/mesa_shader_cache). Given a folder, Mesa keeps its cache in a
/// mesa_shader_cache folder inside it, so the graded programs' cache sits within
/// the window's, apart from it, in the one folder they may write.
std::filesystem::path userShaderCache();

} // namespace stoa::grader
