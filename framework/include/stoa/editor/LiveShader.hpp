#pragma once
// A program whose fragment stage is edited while it draws (stoa-editor's
// shader panel): each accepted edit recompiles; when the text does not
// compile, the last program that did keeps drawing and error() says where,
// at the line of the edited text (the driver's log translated through
// ShaderSource, so an error inside an #include names that file).
//
//   LiveShader lit("editor/lit.vert", "editor/lit.frag", {paths::shadersDir()});
//   if (!lit.setFragmentText(edited)) showError(lit.errorLine(), lit.error());
//   lit.program().use();                     // the last good program

#include <stoa/gl/Program.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace stoa {

class LiveShader {
public:
    /// Loads and compiles both files (found as ShaderSource::load() finds
    /// them). Throws InputError/ShaderError when they do not compile: there is
    /// no good program to fall back on yet.
    LiveShader(std::filesystem::path vertexFile, std::filesystem::path fragmentFile,
               std::vector<std::filesystem::path> searchPath);

    /// The fragment stage's text as last set (compiled or not).
    const std::string& fragmentText() const { return m_text; }
    /// Compiles `text` as the fragment stage. True when it compiled and links:
    /// program() draws with it from now on. False: program() stays the last
    /// good one, error() and errorLine() say what is wrong.
    bool setFragmentText(std::string text);
    /// The last program that compiled.
    const Program& program() const { return m_program; }
    /// Bumped whenever program() is a new GL program (uniform locations and
    /// block bindings must be set again).
    int generation() const { return m_generation; }

    /// The first error of the last setFragmentText() (empty when it compiled),
    /// as "FILE:LINE: message".
    const std::string& error() const { return m_error; }
    /// Its line in the edited text; 0 when it compiled or when the error lies
    /// in an included file or the vertex stage.
    int errorLine() const { return m_errorLine; }

    /// The fragment file the text came from (absolute).
    const std::filesystem::path& fragmentFile() const { return m_fragmentFile; }
    /// Writes fragmentText() to fragmentFile() the way the editor saves a scene
    /// (saveFileSafely in SafeSave.hpp: a temporary file renamed over it, so a
    /// crash mid-write loses nothing; a read-only file, a folder or a device is
    /// refused). Throws InputError naming the file when it cannot or must not write.
    void saveToFile() const;

private:
    std::filesystem::path m_vertexFile;
    std::filesystem::path m_fragmentFile;
    std::vector<std::filesystem::path> m_searchPath;
    std::string m_text;
    Program m_program;
    int m_generation = 0;
    std::string m_error;
    int m_errorLine = 0;
};

} // namespace stoa
