#include <stoa/editor/LiveShader.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/gl/ShaderSource.hpp>

#include "SafeSave.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

namespace stoa {

namespace fs = std::filesystem;

namespace {
fs::path found(const fs::path& file, const std::vector<fs::path>& searchPath) {
    std::error_code error;
    if (fs::exists(file, error)) return fs::absolute(file).lexically_normal();
    for (const fs::path& folder : searchPath)
        if (fs::exists(folder / file, error)) return fs::absolute(folder / file).lexically_normal();
    return file;   // ShaderSource::load names it with the folders searched
}

std::string readAll(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file.string(), 0, "cannot read the shader file");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}
} // namespace

LiveShader::LiveShader(fs::path vertexFile, fs::path fragmentFile, std::vector<fs::path> searchPath)
    : m_vertexFile(found(vertexFile, searchPath)), m_fragmentFile(found(fragmentFile, searchPath)),
      m_searchPath(std::move(searchPath)) {
    m_program = Program::fromFiles(m_vertexFile, m_fragmentFile, m_searchPath);
    m_text = readAll(m_fragmentFile);
    m_generation = 1;
}

bool LiveShader::setFragmentText(std::string text) {
    m_text = std::move(text);
    try {
        const ShaderSource vertex = ShaderSource::load(m_vertexFile, m_searchPath);
        const ShaderSource fragment = ShaderSource::fromText(m_text, m_fragmentFile, m_searchPath);
        Program compiled = Program::fromSources(vertex, fragment);
        m_program = std::move(compiled);
        ++m_generation;
        m_error.clear();
        m_errorLine = 0;
        return true;
    } catch (const InputError& error) {
        m_error = error.what();
        m_errorLine = fs::path(error.file()).lexically_normal() == m_fragmentFile ? error.line() : 0;
        return false;
    }
}

void LiveShader::saveToFile() const {
    saveFileSafely(m_fragmentFile, m_text, "the shader");
}

} // namespace stoa
