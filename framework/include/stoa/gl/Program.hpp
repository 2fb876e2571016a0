#pragma once
// A linked GLSL program built from files: #include expansion, errors that name
// file and line, cached uniform locations, and reloading when a file changes.
//
//   Program program = Program::fromFiles("lit.vert", "lit.frag", {labDir, paths::shadersDir()});
//   program.use();
//   program.set("uModel", modelMatrix);   // by name: the location is looked up once and cached
//   mesh.draw();
//
// Setting a uniform never changes which program is in use: set() on a program
// that is not current makes it current, sets, and makes the previous one
// current again (the StateCache knows which, without asking GL). Draw with
// the program you use(). In a loop over many objects, look the locations up
// once (uniformLocation()) and set them with setAt(), which needs the program
// in use.
//   if (program.reloadIfChanged()) ...    // each frame in an interactive app

#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Shader.hpp>
#include <stoa/gl/ShaderSource.hpp>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

namespace stoa {

class Program {
public:
    /// No program; no GL call.
    Program() = default;

    /// Compiles and links the two stages. Shader files are found as
    /// ShaderSource::load() finds them. Throws InputError for a missing file or
    /// include and ShaderError (message with every error line, file() and
    /// line() at the first one) when a stage does not compile or link.
    static Program fromFiles(const std::filesystem::path& vertex, const std::filesystem::path& fragment,
                             const std::vector<std::filesystem::path>& searchPath);
    /// The same with a geometry shader between the two.
    static Program fromFiles(const std::filesystem::path& vertex, const std::filesystem::path& geometry,
                             const std::filesystem::path& fragment, const std::vector<std::filesystem::path>& searchPath);
    /// From sources already expanded (e.g. ShaderSource::fromText). Such a
    /// program has no files of its own to watch: reloadIfChanged() is false.
    static Program fromSources(const ShaderSource& vertex, const ShaderSource& fragment);

    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;
    Program(Program&& other) noexcept;
    Program& operator=(Program&& other) noexcept;

    /// Makes this program the one draws use (through the StateCache: no call
    /// when it is in use already). Asserts that the program is not empty.
    void use() const;

    /// The uniform's location, asked once and cached; -1 when the program has
    /// no active uniform of that name (the compiler drops unused ones).
    GLint uniformLocation(const std::string& name) const;

    /// Sets a uniform of this program; the program in use stays in use (see
    /// above). A name the program does not use is ignored (location -1), so a
    /// shader can drop a uniform while you edit it. Arrays: "uLights[2].color", or the vector overloads from
    /// element 0 ("uKernel" or "uKernel[0]").
    void set(const std::string& name, int value) const;
    void set(const std::string& name, std::uint32_t value) const;
    void set(const std::string& name, float value) const;
    void set(const std::string& name, double value) const; // GLSL 330 has no double uniforms: sent as float
    void set(const std::string& name, bool value) const;
    void set(const std::string& name, const glm::vec2& value) const;
    void set(const std::string& name, const glm::vec3& value) const;
    void set(const std::string& name, const glm::vec4& value) const;
    void set(const std::string& name, const glm::mat3& value) const;
    void set(const std::string& name, const glm::mat4& value) const;
    void set(const std::string& name, const std::vector<float>& values) const;
    void set(const std::string& name, const std::vector<glm::vec3>& values) const;
    void set(const std::string& name, const std::vector<glm::vec4>& values) const;
    void set(const std::string& name, const std::vector<glm::mat4>& values) const;

    /// Rebuilds the program when a source file (includes too) changed on disk
    /// since the last build or attempt. On success the new program replaces the
    /// old (same Program object, fresh id, uniforms to set again) and the
    /// result is true. On an error the old program stays, lastError() says why
    /// and the result is false: a compile error is retried once a file changes
    /// again, a missing file or include at every call until it appears.
    bool reloadIfChanged();

    /// Sets the uniform at `location` (from uniformLocation(); -1 is ignored).
    /// The program must be in use (checked: asserts otherwise). For per-object
    /// uniforms in a draw loop: no name lookup, no program switch.
    void setAt(GLint location, int value) const;
    void setAt(GLint location, float value) const;
    void setAt(GLint location, bool value) const;
    void setAt(GLint location, const glm::vec3& value) const;
    void setAt(GLint location, const glm::vec4& value) const;
    void setAt(GLint location, const glm::mat3& value) const;
    void setAt(GLint location, const glm::mat4& value) const;

    /// Binds uniform block `blockName` to binding point `binding` (a
    /// UniformBuffer bound there feeds it). Ignored when the program has no such block.
    void bindUniformBlock(const std::string& blockName, GLuint binding) const;
    /// The message of the last failed reload; empty after a successful one.
    const std::string& lastError() const { return m_lastError; }

    /// The STOA_NOT_IMPLEMENTED(...) calls of all stages (each place once).
    const std::vector<ShaderStub>& stubs() const { return m_stubs; }
    /// Every file the program was built from, includes too.
    const std::vector<std::filesystem::path>& files() const { return m_files; }

    GLuint id() const { return m_id; } // 0 when empty
    /// Gives up ownership: returns the id and leaves this Program empty.
    GLuint release();

private:
    struct Stage {
        GLenum type;
        std::filesystem::path path;
    };
    struct FileStamp {
        std::filesystem::path path;
        bool exists = false;
        std::filesystem::file_time_type modified{};
        std::uintmax_t size = 0;
        bool operator==(const FileStamp& other) const;
    };

    static Program build(const std::vector<Stage>& stages, const std::vector<std::filesystem::path>& searchPath);
    static Program link(const std::vector<const ShaderSource*>& sources);
    static std::vector<FileStamp> stampsOf(const std::vector<std::filesystem::path>& files);

    GLuint m_id = 0;
    std::vector<Stage> m_stages; // empty for fromSources(): nothing to reload
    std::vector<std::filesystem::path> m_searchPath;
    std::vector<std::filesystem::path> m_files;
    std::vector<FileStamp> m_watched; // the files of the last build or attempt, as they were then
    std::vector<ShaderStub> m_stubs;
    std::string m_lastError;
    mutable std::unordered_map<std::string, GLint> m_uniformLocations;
};

} // namespace stoa
