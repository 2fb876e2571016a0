#include <stoa/gl/ShaderSource.hpp>

#include <stoa/core/InputError.hpp>

#include <cctype>
#include <cstring>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace stoa {

namespace {

// The stub macro every shader gets: a stub compiles to its neutral value.
const char* const kStubMacro = "#define STOA_NOT_IMPLEMENTED(value) (value)";
const char* const kStubName = "STOA_NOT_IMPLEMENTED";

std::string displayName(const fs::path& path) { return path.lexically_normal().generic_string(); }

// The key under which a file counts as "already included": its real location.
std::string identity(const fs::path& path) {
    std::error_code error;
    const fs::path canonical = fs::weakly_canonical(path, error);
    return (error ? fs::absolute(path) : canonical).lexically_normal().generic_string();
}

bool isRegularFile(const fs::path& path) {
    std::error_code error;
    return fs::is_regular_file(path, error);
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(displayName(path), 0, "cannot read the file");
    std::ostringstream text;
    text << in.rdbuf();
    std::string content = text.str();
    if (content.compare(0, 3, "\xEF\xBB\xBF") == 0) content.erase(0, 3); // a UTF-8 byte order mark
    return content;
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
        start = end + 1;
    }
    return lines;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// `line` with its comments blanked out (columns kept); `inBlockComment`
// carries a /* ... */ from one line to the next.
std::string withoutComments(const std::string& line, bool& inBlockComment) {
    std::string code = line;
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (inBlockComment) {
            if (code.compare(i, 2, "*/") == 0) {
                code[i] = code[i + 1] = ' ';
                ++i;
                inBlockComment = false;
            } else {
                code[i] = ' ';
            }
        } else if (code.compare(i, 2, "//") == 0) {
            code.replace(i, std::string::npos, code.size() - i, ' ');
            break;
        } else if (code.compare(i, 2, "/*") == 0) {
            code[i] = code[i + 1] = ' ';
            ++i;
            inBlockComment = true;
        }
    }
    return code;
}

// The directive name of a preprocessor line ("version", "include"), or "".
std::string directiveOf(const std::string& code) {
    std::size_t at = code.find_first_not_of(" \t");
    if (at == std::string::npos || code[at] != '#') return "";
    at = code.find_first_not_of(" \t", at + 1);
    if (at == std::string::npos) return "";
    std::size_t end = at;
    while (end < code.size() && isIdentifierChar(code[end])) ++end;
    return code.substr(at, end - at);
}

bool isBlank(const std::string& code) { return code.find_first_not_of(" \t") == std::string::npos; }

// Follows the braces of one file to name the function each line lies in:
// at depth 0, the text before a `{` that contains `name(` declares a function.
class FunctionTracker {
public:
    void feed(const std::string& code) {
        for (const char c : code) {
            if (c == '{') {
                if (m_depth == 0) m_function = functionNameIn(m_pending);
                ++m_depth;
                m_pending.clear();
            } else if (c == '}') {
                if (m_depth > 0 && --m_depth == 0) m_function.clear();
                m_pending.clear();
            } else if (c == ';' && m_depth == 0) {
                m_pending.clear();
            } else if (m_depth == 0) {
                m_pending += c;
            }
        }
    }

    void endLine() {
        if (m_depth == 0) m_pending += ' ';
    }

    /// The function the text fed so far ends inside, or "".
    const std::string& current() const { return m_function; }

private:
    static std::string functionNameIn(const std::string& header) {
        const std::size_t paren = header.find('(');
        if (paren == std::string::npos) return "";
        std::size_t end = paren;
        while (end > 0 && std::isspace(static_cast<unsigned char>(header[end - 1]))) --end;
        std::size_t start = end;
        while (start > 0 && isIdentifierChar(header[start - 1])) --start;
        const std::string name = header.substr(start, end - start);
        return name == "layout" ? "" : name; // layout(std140) uniform Block { ... } is no function
    }

    int m_depth = 0;
    std::string m_pending; // depth-0 text since the last ';', '{' or '}'
    std::string m_function;
};

// The column of each STOA_NOT_IMPLEMENTED( call in a comment-free line.
std::vector<std::size_t> stubColumns(const std::string& code) {
    std::vector<std::size_t> columns;
    const std::size_t length = std::strlen(kStubName);
    for (std::size_t at = code.find(kStubName); at != std::string::npos; at = code.find(kStubName, at + length)) {
        if (at > 0 && isIdentifierChar(code[at - 1])) continue;
        std::size_t next = at + length;
        if (next < code.size() && isIdentifierChar(code[next])) continue;
        next = code.find_first_not_of(" \t", next);
        if (next != std::string::npos && code[next] == '(') columns.push_back(at);
    }
    return columns;
}

std::string joined(const std::vector<std::string>& items, const char* separator) {
    std::string result;
    for (const std::string& item : items) result += (result.empty() ? "" : separator) + item;
    return result;
}

} // namespace

// Builds one ShaderSource: a depth-first walk over the include graph.
class ShaderExpander {
public:
    ShaderExpander(ShaderSource& result, const std::vector<fs::path>& searchPath)
        : m_result(result), m_searchPath(searchPath) {}

    void expandTop(const std::string& text, const fs::path& path) { expand(text, path, /*isTop=*/true); }

private:
    struct Open {
        std::string identity;
        std::string name;
    };

    void expand(const std::string& text, const fs::path& path, bool isTop) {
        const int index = static_cast<int>(m_result.m_files.size());
        const std::string name = displayName(path);
        m_result.m_files.push_back(path.lexically_normal());
        m_open.push_back({identity(path), name});

        bool inBlockComment = false;
        int commentOpenedOn = 0; // the line of the /* still open, when inBlockComment
        bool versionSeen = !isTop;
        FunctionTracker tracker;
        const std::vector<std::string> lines = splitLines(text);
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const int lineNumber = static_cast<int>(i) + 1;
            const std::string& line = lines[i];
            const bool wasInComment = inBlockComment;
            const std::string code = withoutComments(line, inBlockComment);
            if (inBlockComment && !wasInComment) commentOpenedOn = lineNumber;
            const std::string directive = directiveOf(code);

            if (!versionSeen) {
                if (isBlank(code)) {
                    emit(line, index, lineNumber);
                    continue;
                }
                if (directive != "version")
                    throw InputError(name, lineNumber,
                                     "expected '#version 330 core' as the first line (only comments may precede it)");
                versionSeen = true;
                emit(line, index, lineNumber);
                emit(kStubMacro, index, lineNumber); // errors there are #version's
                continue;
            }
            if (directive == "version") {
                if (isTop)
                    throw InputError(name, lineNumber, "a second #version; it belongs on the first line only");
                throw InputError(name, lineNumber,
                                 "#version in an included file; only the top shader file may have one");
            }
            if (directive == "include") {
                include(line, name, path, lineNumber, index);
                continue;
            }
            if (directive.empty()) {
                std::size_t fed = 0;
                for (std::size_t column : stubColumns(code)) {
                    tracker.feed(code.substr(fed, column - fed));
                    fed = column;
                    m_result.m_stubs.push_back({name, lineNumber, tracker.current()});
                }
                tracker.feed(code.substr(fed));
                tracker.endLine();
            }
            emit(line, index, lineNumber);
        }
        // Left open, the comment would swallow the including file's next lines.
        if (inBlockComment) throw InputError(name, commentOpenedOn, "this /* comment is never closed");
        if (!versionSeen)
            throw InputError(name, 0, "expected '#version 330 core' as the first line, found no #version");

        m_done.insert(m_open.back().identity);
        m_open.pop_back();
    }

    void include(const std::string& line, const std::string& includingName, const fs::path& includingPath,
                 int lineNumber, int includingIndex) {
        const std::size_t open = line.find('"');
        const std::size_t close = open == std::string::npos ? open : line.find('"', open + 1);
        if (close == std::string::npos || close == open + 1)
            throw InputError(includingName, lineNumber, "expected #include \"name\" (a file name in double quotes)");
        const std::string requested = line.substr(open + 1, close - open - 1);

        std::vector<fs::path> folders{includingPath.parent_path()};
        folders.insert(folders.end(), m_searchPath.begin(), m_searchPath.end());
        fs::path found;
        for (const fs::path& folder : folders) {
            const fs::path candidate = folder / requested;
            if (isRegularFile(candidate)) {
                found = candidate;
                break;
            }
        }
        if (found.empty()) {
            std::vector<std::string> searched;
            for (const fs::path& folder : folders) searched.push_back(folder.empty() ? "." : displayName(folder));
            throw InputError(includingName, lineNumber,
                             "cannot find include '" + requested + "' (searched: " + joined(searched, ", ") + ")");
        }

        const std::string key = identity(found);
        for (std::size_t i = 0; i < m_open.size(); ++i) {
            if (m_open[i].identity != key) continue;
            std::vector<std::string> chain;
            for (std::size_t j = i; j < m_open.size(); ++j) chain.push_back(m_open[j].name);
            chain.push_back(displayName(found));
            throw InputError(includingName, lineNumber, "include cycle: " + joined(chain, " -> "));
        }
        if (m_done.count(key)) {
            emit("", includingIndex, lineNumber); // included before: once only
            return;
        }
        expand(readFile(found), found, /*isTop=*/false);
    }

    void emit(const std::string& line, int file, int lineNumber) {
        m_result.m_text += line;
        m_result.m_text += '\n';
        m_result.m_origins.push_back({file, lineNumber});
    }

    ShaderSource& m_result;
    const std::vector<fs::path>& m_searchPath;
    std::vector<Open> m_open;   // the include chain being expanded, top file first
    std::set<std::string> m_done; // files expanded completely
};

ShaderSource ShaderSource::load(const fs::path& path, const std::vector<fs::path>& searchPath) {
    fs::path found;
    if (isRegularFile(path)) {
        found = path;
    } else if (path.is_relative()) {
        for (const fs::path& folder : searchPath) {
            if (isRegularFile(folder / path)) {
                found = folder / path;
                break;
            }
        }
    }
    if (found.empty()) {
        std::vector<std::string> searched{"."};
        if (path.is_relative())
            for (const fs::path& folder : searchPath) searched.push_back(displayName(folder));
        throw InputError(displayName(path), 0, "cannot find the shader file (searched: " + joined(searched, ", ") + ")");
    }
    return fromText(readFile(found), found, searchPath);
}

ShaderSource ShaderSource::fromText(const std::string& text, const fs::path& name, const std::vector<fs::path>& searchPath) {
    ShaderSource source;
    ShaderExpander(source, searchPath).expandTop(text, name);
    return source;
}

namespace {

struct LogPlace {
    int file = 0;
    int line = 0;
    std::string rest; // the message after the place, e.g. "error: `x' undeclared"
};

std::optional<LogPlace> parseLogLine(const std::string& line) {
    // Mesa: "0:12(5): error: ...", NVIDIA: "0(12) : error C1008: ...", AMD: "ERROR: 0:12: ...".
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    static const std::regex amd(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");
    std::smatch match;
    if (std::regex_match(line, match, mesa) || std::regex_match(line, match, nvidia))
        return LogPlace{std::stoi(match[1]), std::stoi(match[2]), match[3]};
    if (std::regex_match(line, match, amd)) {
        const std::string severity = match[1] == "ERROR" ? "error: " : "warning: ";
        return LogPlace{std::stoi(match[2]), std::stoi(match[3]), severity + match[4].str()};
    }
    return std::nullopt;
}

bool mentionsError(const std::string& text) {
    std::string lower;
    for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower.find("error") != std::string::npos;
}

} // namespace

std::optional<ShaderLocation> ShaderSource::origin(int expandedLine) const {
    if (expandedLine < 1 || expandedLine > static_cast<int>(m_origins.size())) return std::nullopt;
    const LineOrigin& from = m_origins[static_cast<std::size_t>(expandedLine - 1)];
    return ShaderLocation{displayName(m_files[static_cast<std::size_t>(from.file)]), from.line};
}

// The driver's source-string number is ignored: there is one string, and Mesa
// reports 0 for errors inside expressions whatever #line said (see the header).
std::string ShaderSource::translateLog(const std::string& log) const {
    std::string result;
    for (const std::string& line : splitLines(log)) {
        const std::optional<LogPlace> place = parseLogLine(line);
        const std::optional<ShaderLocation> location = place ? origin(place->line) : std::nullopt;
        if (location)
            result += location->file + ":" + std::to_string(location->line) + ": " + place->rest + "\n";
        else
            result += line + "\n";
    }
    return result;
}

std::optional<ShaderLocation> ShaderSource::firstError(const std::string& log) const {
    std::optional<ShaderLocation> first;
    for (const std::string& line : splitLines(log)) {
        const std::optional<LogPlace> place = parseLogLine(line);
        const std::optional<ShaderLocation> location = place ? origin(place->line) : std::nullopt;
        if (!location) continue;
        if (mentionsError(place->rest)) return location;
        if (!first) first = location;
    }
    return first;
}

} // namespace stoa
