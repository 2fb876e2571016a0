#include "MistakeFile.hpp"

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace stoa::grader {

namespace {

std::string trimmed(const std::string& text) {
    std::size_t begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos) return "";
    std::size_t end = text.find_last_not_of(" \t\r");
    return text.substr(begin, end + 1 - begin);
}

std::vector<std::string> words(const std::string& text) {
    std::istringstream stream(text);
    std::vector<std::string> list;
    for (std::string word; stream >> word;) list.push_back(word);
    return list;
}

} // namespace

MistakeFile parseMistakeHeader(const std::string& text, const std::string& fileName) {
    MistakeFile mistake;
    mistake.path = fileName;
    mistake.name = std::filesystem::path(fileName).stem().string();

    std::istringstream stream(text);
    std::set<std::string> seen;
    int lineNumber = 0;
    for (std::string line; std::getline(stream, line);) {
        ++lineNumber;
        if (line.rfind("--- ", 0) == 0 || trimmed(line) == "---") break;
        std::string content = trimmed(line);
        if (content.empty() || content[0] == '#') continue;
        std::size_t colon = content.find(':');
        if (colon == std::string::npos)
            throw InputError(fileName, lineNumber,
                             "expected 'key: value' (keys: hint, docs, fails, file, hint-ok) before the '--- find' block, "
                             "got '" + content + "'");
        std::string key = trimmed(content.substr(0, colon));
        std::string value = trimmed(content.substr(colon + 1));
        if (!seen.insert(key).second) throw InputError(fileName, lineNumber, "the key '" + key + "' appears twice");
        if (key == "hint") {
            mistake.hint = value;
        } else if (key == "docs") {
            mistake.docs = value;
        } else if (key == "fails") {
            mistake.fails = words(value);
            if (mistake.fails.empty())
                throw InputError(fileName, lineNumber, "'fails:' needs the names of the cases this mistake must fail");
        } else if (key == "file") {
            mistake.file = value;
        } else if (key == "hint-ok") {
            mistake.hintOk = words(value);
        } else {
            throw InputError(fileName, lineNumber,
                             "unknown key '" + key + "'; expected hint, docs, fails, file or hint-ok");
        }
    }
    for (const char* required : {"hint", "fails", "file"})
        if (!seen.count(required))
            throw InputError(fileName, 0, std::string("missing '") + required + ":' line in the header");
    if (mistake.hint.empty()) throw InputError(fileName, 0, "'hint:' is empty; say what the student should look at");
    if (mistake.file.empty()) throw InputError(fileName, 0, "'file:' is empty; name the student file it changes");
    return mistake;
}

MistakeFile loadMistakeFile(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path.string(), 0, "cannot read the mistake file");
    std::ostringstream text;
    text << file.rdbuf();
    MistakeFile mistake = parseMistakeHeader(text.str(), path.string());
    mistake.lab = path.parent_path().parent_path().filename().string();
    return mistake;
}

std::vector<MistakeFile> loadMistakes(const std::filesystem::path& labSolutionsDir) {
    std::vector<MistakeFile> mistakes;
    std::filesystem::path folder = labSolutionsDir / "mistakes";
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) return mistakes;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".mistake") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const std::filesystem::path& file : files) mistakes.push_back(loadMistakeFile(file));
    return mistakes;
}

} // namespace stoa::grader
