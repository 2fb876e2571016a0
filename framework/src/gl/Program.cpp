#include <stoa/gl/Program.hpp>

#include <stoa/core/Assert.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/StateCache.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>

namespace fs = std::filesystem;

namespace stoa {

namespace {

std::string programLog(GLuint program) {
    GLint length = 0;
    STOA_GL_CALL(glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length));
    if (length <= 1) return "";
    std::string log(static_cast<std::size_t>(length), '\0');
    STOA_GL_CALL(glGetProgramInfoLog(program, length, nullptr, log.data()));
    log.resize(std::min(log.find('\0'), log.size()));
    while (!log.empty() && (log.back() == '\n' || log.back() == ' ')) log.pop_back();
    return log;
}

// Each file once, in the order first met.
void appendFiles(std::vector<fs::path>& files, const std::vector<fs::path>& more) {
    for (const fs::path& file : more)
        if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
}

} // namespace

bool Program::FileStamp::operator==(const FileStamp& other) const {
    return std::tie(path, exists, modified, size) == std::tie(other.path, other.exists, other.modified, other.size);
}

std::vector<Program::FileStamp> Program::stampsOf(const std::vector<fs::path>& files) {
    std::vector<FileStamp> stamps;
    for (const fs::path& file : files) {
        FileStamp stamp;
        stamp.path = file;
        std::error_code error;
        stamp.modified = fs::last_write_time(file, error);
        if (!error) stamp.size = fs::file_size(file, error);
        stamp.exists = !error;
        stamps.push_back(stamp);
    }
    return stamps;
}

Program Program::link(const std::vector<const ShaderSource*>& sources) {
    std::vector<Shader> shaders;
    std::vector<GLenum> stageTypes{GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
    if (sources.size() == 3) stageTypes = {GL_VERTEX_SHADER, GL_GEOMETRY_SHADER, GL_FRAGMENT_SHADER};
    for (std::size_t i = 0; i < sources.size(); ++i) shaders.emplace_back(stageTypes[i], *sources[i]);

    Program program;
    program.m_id = glCreateProgram();
    STOA_GL_CHECK("glCreateProgram");
    for (const Shader& shader : shaders) STOA_GL_CALL(glAttachShader(program.m_id, shader.id()));
    STOA_GL_CALL(glLinkProgram(program.m_id));
    for (const Shader& shader : shaders) STOA_GL_CALL(glDetachShader(program.m_id, shader.id()));
    GLint linked = GL_FALSE;
    STOA_GL_CALL(glGetProgramiv(program.m_id, GL_LINK_STATUS, &linked));
    if (!linked) {
        std::string names;
        for (const ShaderSource* source : sources)
            names += (names.empty() ? "" : " + ") + source->files()[0].generic_string();
        const std::string log = programLog(program.m_id);
        throw ShaderError(sources[0]->files()[0].generic_string(), 0, "Program: cannot link " + names + ":\n" + log,
                          log);
    }

    std::set<std::tuple<std::string, int, std::string>> seen;
    for (const ShaderSource* source : sources) {
        appendFiles(program.m_files, source->files());
        for (const ShaderStub& stub : source->stubs())
            if (seen.insert({stub.file, stub.line, stub.function}).second) program.m_stubs.push_back(stub);
    }
    return program;
}

Program Program::build(const std::vector<Stage>& stages, const std::vector<fs::path>& searchPath) {
    std::vector<ShaderSource> sources;
    for (const Stage& stage : stages) sources.push_back(ShaderSource::load(stage.path, searchPath));
    std::vector<const ShaderSource*> pointers;
    for (const ShaderSource& source : sources) pointers.push_back(&source);
    Program program = link(pointers);
    program.m_stages = stages;
    program.m_searchPath = searchPath;
    program.m_watched = stampsOf(program.m_files);
    return program;
}

Program Program::fromFiles(const fs::path& vertex, const fs::path& fragment, const std::vector<fs::path>& searchPath) {
    return build({{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, searchPath);
}

Program Program::fromFiles(const fs::path& vertex, const fs::path& geometry, const fs::path& fragment,
                           const std::vector<fs::path>& searchPath) {
    return build({{GL_VERTEX_SHADER, vertex}, {GL_GEOMETRY_SHADER, geometry}, {GL_FRAGMENT_SHADER, fragment}},
                 searchPath);
}

Program Program::fromSources(const ShaderSource& vertex, const ShaderSource& fragment) {
    return link({&vertex, &fragment});
}

Program::~Program() {
    if (m_id) {
        StateCache::current().programDeleted(m_id);
        glDeleteProgram(m_id);
    }
}

Program::Program(Program&& other) noexcept
    : m_id(std::exchange(other.m_id, 0)),
      m_stages(std::move(other.m_stages)),
      m_searchPath(std::move(other.m_searchPath)),
      m_files(std::move(other.m_files)),
      m_watched(std::move(other.m_watched)),
      m_stubs(std::move(other.m_stubs)),
      m_lastError(std::move(other.m_lastError)),
      m_uniformLocations(std::move(other.m_uniformLocations)) {}

Program& Program::operator=(Program&& other) noexcept {
    if (this != &other) {
        if (m_id) {
            StateCache::current().programDeleted(m_id);
            glDeleteProgram(m_id);
        }
        m_id = std::exchange(other.m_id, 0);
        m_stages = std::move(other.m_stages);
        m_searchPath = std::move(other.m_searchPath);
        m_files = std::move(other.m_files);
        m_watched = std::move(other.m_watched);
        m_stubs = std::move(other.m_stubs);
        m_lastError = std::move(other.m_lastError);
        m_uniformLocations = std::move(other.m_uniformLocations);
    }
    return *this;
}

GLuint Program::release() {
    m_uniformLocations.clear();
    return std::exchange(m_id, 0);
}

void Program::use() const {
    STOA_ASSERT(m_id != 0, "Program::use(): the program is empty (default-constructed, moved from or released). "
                           "Build it with Program::fromFiles() and keep it alive while you draw with it.");
    StateCache::current().useProgram(m_id);
}

GLint Program::uniformLocation(const std::string& name) const {
    STOA_ASSERT(m_id != 0, "Program::uniformLocation(): the program is empty. Build it with Program::fromFiles().");
    const auto cached = m_uniformLocations.find(name);
    if (cached != m_uniformLocations.end()) return cached->second;
    const GLint location = glGetUniformLocation(m_id, name.c_str());
    m_uniformLocations.emplace(name, location);
    return location;
}

bool Program::reloadIfChanged() {
    if (m_stages.empty()) return false;
    std::vector<fs::path> watchedFiles;
    for (const FileStamp& stamp : m_watched) watchedFiles.push_back(stamp.path);
    if (stampsOf(watchedFiles) == m_watched) return false;

    // A file or include that cannot be found (yet: an editor may still be
    // saving it) leaves the stamps as they were, so the next call looks again.
    // That costs a few small file reads per call and no GL work.
    std::vector<ShaderSource> sources;
    try {
        for (const Stage& stage : m_stages) sources.push_back(ShaderSource::load(stage.path, m_searchPath));
    } catch (const std::exception& error) {
        m_lastError = error.what();
        return false;
    }
    // From here on watch the files of the new version (an edit may add an
    // include), even if it does not compile; a compile error is not retried
    // until one of them changes again.
    std::vector<fs::path> newFiles;
    for (const ShaderSource& source : sources) appendFiles(newFiles, source.files());
    m_watched = stampsOf(newFiles);

    std::vector<const ShaderSource*> pointers;
    for (const ShaderSource& source : sources) pointers.push_back(&source);
    try {
        Program fresh = link(pointers);
        if (m_id) {
            StateCache::current().programDeleted(m_id);
            glDeleteProgram(m_id);
        }
        m_id = std::exchange(fresh.m_id, 0);
        m_files = std::move(fresh.m_files);
        m_stubs = std::move(fresh.m_stubs);
        m_uniformLocations.clear();
        m_lastError.clear();
        return true;
    } catch (const std::exception& error) {
        m_lastError = error.what();
        return false;
    }
}

namespace {

// Every setter: the location (cached), nothing for a name the program does not
// use, else set it with this program current and give the previous one back
// (GL 3.3 has no glProgramUniform). Checked mode names a type mismatch
// (GL_INVALID_OPERATION: set(float) on an int uniform, say).
template <typename Apply>
void setUniform(const Program& program, const std::string& name, Apply apply) {
    const GLint location = program.uniformLocation(name);
    if (location < 0) return;
    StateCache& cache = StateCache::current();
    const GLuint previous = cache.program();
    cache.useProgram(program.id());
    apply(location);
    STOA_GL_CHECK(("Program::set(\"" + name + "\")").c_str());
    cache.useProgram(previous);
}

template <typename Apply>
void setUniformAt(const Program& program, GLint location, Apply apply) {
    if (location < 0) return;
    STOA_ASSERT(StateCache::current().program() == program.id(),
                "Program::setAt(): the program is not in use. Call program.use() before the draw loop "
                "(or set by name with Program::set(), which switches and switches back).");
    apply(location);
    STOA_GL_CHECK("Program::setAt()");
}

} // namespace

void Program::set(const std::string& name, int value) const {
    setUniform(*this, name, [&](GLint at) { glUniform1i(at, value); });
}
void Program::set(const std::string& name, std::uint32_t value) const {
    setUniform(*this, name, [&](GLint at) { glUniform1ui(at, value); });
}
void Program::set(const std::string& name, float value) const {
    setUniform(*this, name, [&](GLint at) { glUniform1f(at, value); });
}
void Program::set(const std::string& name, double value) const { set(name, static_cast<float>(value)); }
void Program::set(const std::string& name, bool value) const { set(name, value ? 1 : 0); }
void Program::set(const std::string& name, const glm::vec2& value) const {
    setUniform(*this, name, [&](GLint at) { glUniform2fv(at, 1, glm::value_ptr(value)); });
}
void Program::set(const std::string& name, const glm::vec3& value) const {
    setUniform(*this, name, [&](GLint at) { glUniform3fv(at, 1, glm::value_ptr(value)); });
}
void Program::set(const std::string& name, const glm::vec4& value) const {
    setUniform(*this, name, [&](GLint at) { glUniform4fv(at, 1, glm::value_ptr(value)); });
}
void Program::set(const std::string& name, const glm::mat3& value) const {
    setUniform(*this, name, [&](GLint at) { glUniformMatrix3fv(at, 1, GL_FALSE, glm::value_ptr(value)); });
}
void Program::set(const std::string& name, const glm::mat4& value) const {
    setUniform(*this, name, [&](GLint at) { glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(value)); });
}

// Arrays: `count` elements from the location of element 0.
void Program::set(const std::string& name, const std::vector<float>& values) const {
    if (values.empty()) return;
    const auto count = static_cast<GLsizei>(values.size());
    setUniform(*this, name, [&](GLint at) { glUniform1fv(at, count, values.data()); });
}
void Program::set(const std::string& name, const std::vector<glm::vec3>& values) const {
    if (values.empty()) return;
    const auto count = static_cast<GLsizei>(values.size());
    setUniform(*this, name, [&](GLint at) { glUniform3fv(at, count, glm::value_ptr(values[0])); });
}
void Program::set(const std::string& name, const std::vector<glm::vec4>& values) const {
    if (values.empty()) return;
    const auto count = static_cast<GLsizei>(values.size());
    setUniform(*this, name, [&](GLint at) { glUniform4fv(at, count, glm::value_ptr(values[0])); });
}
void Program::set(const std::string& name, const std::vector<glm::mat4>& values) const {
    if (values.empty()) return;
    const auto count = static_cast<GLsizei>(values.size());
    setUniform(*this, name,
               [&](GLint at) { glUniformMatrix4fv(at, count, GL_FALSE, glm::value_ptr(values[0])); });
}

void Program::setAt(GLint location, int value) const {
    setUniformAt(*this, location, [&](GLint at) { glUniform1i(at, value); });
}
void Program::setAt(GLint location, float value) const {
    setUniformAt(*this, location, [&](GLint at) { glUniform1f(at, value); });
}
void Program::setAt(GLint location, bool value) const { setAt(location, value ? 1 : 0); }
void Program::setAt(GLint location, const glm::vec3& value) const {
    setUniformAt(*this, location, [&](GLint at) { glUniform3fv(at, 1, glm::value_ptr(value)); });
}
void Program::setAt(GLint location, const glm::vec4& value) const {
    setUniformAt(*this, location, [&](GLint at) { glUniform4fv(at, 1, glm::value_ptr(value)); });
}
void Program::setAt(GLint location, const glm::mat3& value) const {
    setUniformAt(*this, location, [&](GLint at) { glUniformMatrix3fv(at, 1, GL_FALSE, glm::value_ptr(value)); });
}
void Program::setAt(GLint location, const glm::mat4& value) const {
    setUniformAt(*this, location, [&](GLint at) { glUniformMatrix4fv(at, 1, GL_FALSE, glm::value_ptr(value)); });
}

void Program::bindUniformBlock(const std::string& blockName, GLuint binding) const {
    STOA_ASSERT(m_id != 0, "Program::bindUniformBlock(): the program is empty. Build it with Program::fromFiles().");
    const GLuint index = glGetUniformBlockIndex(m_id, blockName.c_str());
    if (index == GL_INVALID_INDEX) return;
    STOA_GL_CALL(glUniformBlockBinding(m_id, index, binding));
}

} // namespace stoa
