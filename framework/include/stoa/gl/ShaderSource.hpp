#pragma once
// GLSL source with its `#include "name"` lines expanded, ready for
// glShaderSource. Needs no GL context (part of stoa_core), so the grader and
// the tests can list a lab's GLSL stubs without a driver.
//
// The driver's messages still point at the right place: ShaderSource knows
// which file and line every line of the expanded text came from, and
// translateLog() turns the driver's "0:57(5): error: ..." back into
// "shaders/common/lights.glsl:12: error: ...".
//
// Why no `#line N K` directives: Mesa (22.3, llvmpipe) honours the line
// number of `#line` (the next line is N) but reports source string 0 for
// errors inside expressions, e.g. "0:2(15): error: `x' undeclared" for a
// mistake in string 2. With one string and no #line, the line number alone
// identifies file and line on every driver.
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

    /// Every file in the expansion, in the order first included; files()[0] is the top file.
    const std::vector<std::filesystem::path>& files() const { return m_files; }

    /// The file and line that line `expandedLine` (1-based) of text() comes
    /// from; nothing outside text(). The inserted #define counts as the
    /// #version line, a repeated (skipped) #include as the #include line.
    std::optional<ShaderLocation> origin(int expandedLine) const;

    /// The STOA_NOT_IMPLEMENTED(...) calls outside comments, in file order.
    const std::vector<ShaderStub>& stubs() const { return m_stubs; }

    /// Rewrites a driver's info log so that each message names its file:
    ///   Mesa    "K:L(C): error: ..."      -> "path/file.glsl:L: error: ..."
    ///   NVIDIA  "K(L) : error C0000: ..." -> "path/file.glsl:L: error C0000: ..."
    ///   AMD     "ERROR: K:L: ..."         -> "path/file.glsl:L: error: ..."
    /// where L is a line of text() (K, the source string, is always 0 here).
    /// Other lines, and lines past the end of text(), are kept as they are.
    std::string translateLog(const std::string& log) const;

    /// Where the first error of `log` lies (the first message when none says
    /// "error"); nothing when no line of the log names a place in these files.
    std::optional<ShaderLocation> firstError(const std::string& log) const;

private:
    friend class ShaderExpander;

    struct LineOrigin {
        int file; // index into m_files
        int line; // 1-based
    };

    std::string m_text;
    std::vector<std::filesystem::path> m_files;
    std::vector<LineOrigin> m_origins; // one per line of m_text
    std::vector<ShaderStub> m_stubs;
};

} // namespace stoa
