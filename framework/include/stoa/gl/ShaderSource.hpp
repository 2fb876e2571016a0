#pragma once
// GLSL source with its `#include "name"` lines expanded, ready for
// glShaderSource. Needs no GL context (part of stoa_core), so the grader and
// the tests can list a lab's GLSL stubs without a driver.
//
// The expanded text keeps the driver's error lines meaningful: every file gets
// a source-string number K (its index in files()) and `#line N K` directives
// restore its own line numbers, so translateLog() can turn the driver's
// "1:12(5): error: ..." back into "shaders/common/lighting.glsl:12: error: ...".
//
//   ShaderSource source = ShaderSource::load("lab02/blinn_phong.frag", {labDir, paths::shadersDir()});
//   glShaderSource(id, 1, &text, nullptr) with text = source.text().c_str()

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace stoa {

/// A call of STOA_NOT_IMPLEMENTED(...) still in the GLSL: a lab stub the
/// student has not replaced yet.
struct ShaderStub {
    std::string file;     // as in ShaderSource::files()
    int line = 0;         // 1-based, in that file
    std::string function; // the enclosing function's name; empty outside any function
};

/// A place in one of the files of a ShaderSource.
struct ShaderLocation {
    std::string file; // as in ShaderSource::files()
    int line = 0;     // 1-based
};

class ShaderSource {
public:
    /// Reads `path` (as given if it exists, else the first searchPath folder
    /// that holds it) and expands every `#include "name"` recursively. `name` is
    /// looked up next to the including file first, then in each searchPath
    /// folder in order. A file is included once only, however often it is
    /// named ("#pragma once" for every file), so include guards are optional.
    /// Right after the top file's #version line the expansion inserts
    ///     #define STOA_NOT_IMPLEMENTED(value) (value)
    /// Throws InputError(file, line, ...) for a missing file or include (with
    /// the folders searched), an include cycle, a top file whose first
    /// non-comment line is not #version, and #version in an included file.
    static ShaderSource load(const std::filesystem::path& path, const std::vector<std::filesystem::path>& searchPath);

    /// The same for source held in memory; `name` stands for its file in
    /// messages and its folder is where relative includes are looked up first.
    static ShaderSource fromText(const std::string& text, const std::filesystem::path& name,
                                 const std::vector<std::filesystem::path>& searchPath);

    /// The expanded source, for glShaderSource.
    const std::string& text() const { return m_text; }

    /// Every file in the expansion; files()[0] is the top file, files()[K] is
    /// source-string number K in the driver's messages.
    const std::vector<std::filesystem::path>& files() const { return m_files; }

    /// The STOA_NOT_IMPLEMENTED(...) calls outside comments, in file order.
    const std::vector<ShaderStub>& stubs() const { return m_stubs; }

    /// Rewrites a driver's info log so that each message names its file:
    ///   Mesa    "K:L(C): error: ..."      -> "path/file.glsl:L: error: ..."
    ///   NVIDIA  "K(L) : error C0000: ..." -> "path/file.glsl:L: error C0000: ..."
    ///   AMD     "ERROR: K:L: ..."         -> "path/file.glsl:L: error: ..."
    /// Other lines are kept. `lineShift` is how far the driver's line numbers
    /// run ahead of the C rule "the line after `#line N` is line N" (Mesa: 0;
    /// a driver that follows GLSL 3.30's wording "N+1" literally: 1).
    std::string translateLog(const std::string& log, int lineShift = 0) const;

    /// Where the first error of `log` lies (the first message when none says
    /// "error"); nothing when no line of the log names a place in these files.
    std::optional<ShaderLocation> firstError(const std::string& log, int lineShift = 0) const;

private:
    friend class ShaderExpander;

    std::string m_text;
    std::vector<std::filesystem::path> m_files;
    std::vector<ShaderStub> m_stubs;
};

} // namespace stoa
