#include <stoa/lab/CaseManifest.hpp>

#include <stoa/core/InputError.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <locale>
#include <sstream>

namespace stoa {

namespace {

const char* const kBlanks = " \t\r\f\v";

std::string trimmed(const std::string& text) {
    const std::size_t first = text.find_first_not_of(kBlanks);
    if (first == std::string::npos) return {};
    const std::size_t last = text.find_last_not_of(kBlanks);
    return text.substr(first, last - first + 1);
}

std::vector<std::string> words(const std::string& text) {
    std::vector<std::string> result;
    std::size_t start = text.find_first_not_of(kBlanks);
    while (start != std::string::npos) {
        const std::size_t end = text.find_first_of(kBlanks, start);
        result.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        start = end == std::string::npos ? end : text.find_first_not_of(kBlanks, end);
    }
    return result;
}

// The whole of `text` must be the number: "1.5x" and "" are not numbers.
// A stream in the classic locale reads "0.5" the same whatever the user's locale.
bool parseNumber(const std::string& text, double& value) {
    std::istringstream stream(text);
    stream.imbue(std::locale::classic());
    double parsed = 0.0;
    stream >> parsed;
    if (stream.fail() || stream.peek() != std::char_traits<char>::eof() || !std::isfinite(parsed)) return false;
    value = parsed;
    return true;
}

bool parseInt(const std::string& text, int& value) {
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (first != last && *first == '+') ++first;  // from_chars takes '-' but not '+'
    int parsed = 0;
    const auto [end, error] = std::from_chars(first, last, parsed);
    if (error != std::errc() || end != last || first == last) return false;
    value = parsed;
    return true;
}

bool isNameCharacter(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
}

bool isKeyCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Levenshtein distance, for "did you mean" suggestions.
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

bool isIdentifier(const std::string& text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), isKeyCharacter);
}

} // namespace

// The keys of a case that the parser reads itself, in the order the instructor
// guide lists them; any other key is a scene parameter of the lab. This one table
// drives the parsing, the message for a bad value (its `expected`) and the "did
// you mean" suggestions (tests/lab/CaseManifestTests.cpp checks the docs list
// the same keys).
const std::vector<CaseKey>& caseKeys() {
    static const std::vector<CaseKey> keys = {
        {"description", "a one-line description (any text)",
         [](CaseSpec& spec, const std::string& value) {
             spec.description = value;
             return true;
         }},
        {"resolution", "'resolution = WIDTH HEIGHT' with two whole numbers from 1 to 4096",
         [](CaseSpec& spec, const std::string& value) {
             const std::vector<std::string> parts = words(value);
             int width = 0, height = 0;
             if (parts.size() != 2 || !parseInt(parts[0], width) || !parseInt(parts[1], height) || width < 1 ||
                 height < 1 || width > 4096 || height > 4096)
                 return false;
             spec.width = width;
             spec.height = height;
             return true;
         }},
        {"points", "a number of points >= 0",
         [](CaseSpec& spec, const std::string& value) {
             double points = 0.0;
             if (!parseNumber(value, points) || points < 0.0) return false;
             spec.points = points;
             return true;
         }},
        {"visibility", "'visible' or 'hidden' for 'visibility'",
         [](CaseSpec& spec, const std::string& value) {
             if (value != "visible" && value != "hidden") return false;
             spec.visibility = value == "visible" ? Visibility::Visible : Visibility::Hidden;
             return true;
         }},
        {"tolerance", "a tolerance from 0 to 255 levels (a whole number)",
         [](CaseSpec& spec, const std::string& value) {
             int tolerance = 0;
             if (!parseInt(value, tolerance) || tolerance < 0 || tolerance > 255) return false;
             spec.compare.tolerance = tolerance;
             return true;
         }},
        {"max_bad_fraction", "a max_bad_fraction from 0 to 1",
         [](CaseSpec& spec, const std::string& value) {
             double fraction = 0.0;
             if (!parseNumber(value, fraction) || fraction < 0.0 || fraction > 1.0) return false;
             spec.compare.maxBadFraction = fraction;
             return true;
         }},
        {"max_flip_mean", "a max_flip_mean from 0 to 1 (a mean LDR-FLIP error)",
         [](CaseSpec& spec, const std::string& value) {
             double mean = 0.0;
             if (!parseNumber(value, mean) || mean < 0.0 || mean > 1.0) return false;
             spec.compare.maxFlipMean = mean;
             return true;
         }},
        {"check", "'check = NAME' with letters, digits and '_'",
         [](CaseSpec& spec, const std::string& value) {
             if (!isIdentifier(value)) return false;
             spec.check = value;
             return true;
         }},
    };
    return keys;
}

const CaseKey* findCaseKey(const std::string& key) {
    for (const CaseKey& entry : caseKeys())
        if (key == entry.key) return &entry;
    return nullptr;
}

namespace {

// Reads a manifest line by line. Holds the file name and the current line so
// that every error names both.
class ManifestParser {
public:
    explicit ManifestParser(std::string file) : m_file(std::move(file)) { m_manifest.file = m_file; }

    LabManifest parse(const std::string& text) {
        std::istringstream lines(text);
        std::string line;
        while (std::getline(lines, line)) {
            ++m_line;
            // Values never contain '#', so a comment may start anywhere.
            const std::size_t comment = line.find('#');
            if (comment != std::string::npos) line.erase(comment);
            line = trimmed(line);
            if (line.empty()) continue;
            if (line.front() == '[') readSectionHeader(line);
            else readKeyValue(line);
        }
        if (m_manifest.lab.empty()) fail(0, "missing 'lab = NAME' before the first [case NAME] section");
        if (m_manifest.cases.empty()) fail(0, "no [case ...] sections");
        return std::move(m_manifest);
    }

private:
    [[noreturn]] void fail(int line, const std::string& message) const { throw InputError(m_file, line, message); }
    [[noreturn]] void fail(const std::string& message) const { fail(m_line, message); }

    void readSectionHeader(const std::string& line) {
        if (line.back() != ']') fail("expected '[case NAME]', got '" + line + "' (no closing ']')");
        const std::string inside = trimmed(line.substr(1, line.size() - 2));
        if (inside.compare(0, 4, "case") != 0 || (inside.size() > 4 && !std::strchr(kBlanks, inside[4])))
            fail("expected '[case NAME]', got '" + line + "'");
        const std::string name = trimmed(inside.substr(4));
        if (name.empty()) fail("expected '[case NAME]' with a name, got '" + line + "'");
        if (!std::all_of(name.begin(), name.end(), isNameCharacter))
            fail("bad case name '" + name + "': use letters, digits, '_' and '-'");
        for (const CaseSpec& earlier : m_manifest.cases) {
            if (earlier.name == name)
                fail("duplicate case '" + name + "' (first at line " + std::to_string(earlier.line) + ")");
        }
        CaseSpec spec;
        spec.name = name;
        spec.file = m_file;
        spec.line = m_line;
        m_manifest.cases.push_back(std::move(spec));
        m_keyLines.clear();
    }

    void readKeyValue(const std::string& line) {
        const std::size_t equals = line.find('=');
        if (equals == std::string::npos) fail("expected 'key = value', got '" + line + "'");
        const std::string key = trimmed(line.substr(0, equals));
        const std::string value = trimmed(line.substr(equals + 1));
        if (key.empty()) fail("expected a key before '=' in '" + line + "'");
        if (!std::all_of(key.begin(), key.end(), isKeyCharacter))
            fail("bad key '" + key + "': use letters, digits and '_'");

        const bool inCase = !m_manifest.cases.empty();
        const auto [earlier, isNew] = m_keyLines.emplace(key, m_line);
        if (!isNew) {
            const std::string where = inCase ? " in case '" + m_manifest.cases.back().name + "'" : "";
            fail("duplicate key '" + key + "'" + where + " (first at line " + std::to_string(earlier->second) + ")");
        }
        if (inCase) readCaseKey(m_manifest.cases.back(), key, value);
        else readLabKey(key, value);
    }

    void readLabKey(const std::string& key, const std::string& value) {
        if (key == "lab") {
            if (value.empty()) fail("expected 'lab = NAME', e.g. 'lab = 01_transforms'");
            m_manifest.lab = value;
        } else if (key == "title") {
            m_manifest.title = value;
        } else if (findCaseKey(key)) {
            fail("key '" + key + "' is outside any [case NAME] section; put it below the header of its case");
        } else {
            fail("unknown lab-level key '" + key +
                 "': before the first [case NAME] only 'lab' and 'title' are allowed, "
                 "and scene parameters go below the header of their case");
        }
    }

    void readCaseKey(CaseSpec& spec, const std::string& key, const std::string& value) {
        const CaseKey* typed = findCaseKey(key);
        if (!typed) {
            spec.setParameter(key, value, m_line);   // a scene parameter: the lab reads it
            return;
        }
        if (!typed->read(spec, value)) fail("expected " + std::string(typed->expected) + ", got '" + value + "'");
    }

    std::string m_file;
    int m_line = 0;
    LabManifest m_manifest;
    std::map<std::string, int> m_keyLines;  // keys of the current section (or the lab part) and their lines
};

} // namespace

bool CaseSpec::has(const std::string& key) const { return find(key) != nullptr; }

std::string CaseSpec::getString(const std::string& key, std::optional<std::string> fallback) const {
    if (const Parameter* parameter = find(key)) return parameter->value;
    if (fallback) return *fallback;
    throw InputError(file, line, "case '" + name + "' needs a '" + key + " = ...' line");
}

double CaseSpec::getNumber(const std::string& key, std::optional<double> fallback) const {
    const Parameter* parameter = find(key);
    if (!parameter) {
        if (fallback) return *fallback;
        throw InputError(file, line, "case '" + name + "' needs a '" + key + " = NUMBER' line");
    }
    double value = 0.0;
    if (!parseNumber(parameter->value, value)) fail(*parameter, key, "a number");
    return value;
}

int CaseSpec::getInt(const std::string& key, std::optional<int> fallback) const {
    const Parameter* parameter = find(key);
    if (!parameter) {
        if (fallback) return *fallback;
        throw InputError(file, line, "case '" + name + "' needs a '" + key + " = INTEGER' line");
    }
    int value = 0;
    if (!parseInt(parameter->value, value)) fail(*parameter, key, "an integer");
    return value;
}

glm::vec3 CaseSpec::getVec3(const std::string& key, std::optional<glm::vec3> fallback) const {
    const Parameter* parameter = find(key);
    if (!parameter) {
        if (fallback) return *fallback;
        throw InputError(file, line, "case '" + name + "' needs a '" + key + " = X Y Z' line");
    }
    const std::vector<std::string> parts = words(parameter->value);
    double x = 0.0, y = 0.0, z = 0.0;
    if (parts.size() != 3 || !parseNumber(parts[0], x) || !parseNumber(parts[1], y) || !parseNumber(parts[2], z))
        fail(*parameter, key, "three numbers");
    return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

namespace {

std::string formatNumber(double value) {
    std::ostringstream text;
    text.imbue(std::locale::classic());
    text << value;
    return text.str();
}

} // namespace

double CaseSpec::getNumberInRange(const std::string& key, double min, double max,
                                  std::optional<double> fallback) const {
    const double value = getNumber(key, fallback);
    const Parameter* parameter = find(key);
    if (parameter && (value < min || value > max))
        fail(*parameter, key, "a number from " + formatNumber(min) + " to " + formatNumber(max));
    return value;
}

int CaseSpec::getIntInRange(const std::string& key, int min, int max, std::optional<int> fallback) const {
    const int value = getInt(key, fallback);
    const Parameter* parameter = find(key);
    if (parameter && (value < min || value > max))
        fail(*parameter, key, "an integer from " + std::to_string(min) + " to " + std::to_string(max));
    return value;
}

std::vector<float> CaseSpec::getNumbers(const std::string& key, std::size_t count, const std::string& meaning) const {
    const char* const counts[] = {"no numbers", "one number", "two numbers", "three numbers", "four numbers",
                                  "five numbers", "six numbers", "seven numbers", "eight numbers", "nine numbers"};
    const std::string expected =
        (count < std::size(counts) ? std::string(counts[count]) : std::to_string(count) + " numbers") +
        (meaning.empty() ? "" : " (" + meaning + ")");
    const Parameter* parameter = find(key);
    if (!parameter) throw InputError(file, line, "case '" + name + "' needs a '" + key + " = ...' line with " + expected);
    const std::vector<std::string> parts = words(parameter->value);
    std::vector<float> values;
    for (const std::string& part : parts) {
        double value = 0.0;
        if (!parseNumber(part, value)) fail(*parameter, key, expected);
        values.push_back(static_cast<float>(value));
    }
    if (values.size() != count) fail(*parameter, key, expected);
    return values;
}

std::string CaseSpec::getChoice(const std::string& key, const std::vector<std::string>& choices,
                                std::optional<std::string> fallback) const {
    const std::string value = getString(key, fallback);
    if (std::find(choices.begin(), choices.end(), value) != choices.end()) return value;
    std::string expected;
    for (std::size_t i = 0; i < choices.size(); ++i)
        expected += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
    const Parameter* parameter = find(key);
    if (!parameter) throw InputError(file, line, "case '" + name + "': the fallback '" + value + "' for '" + key +
                                                     "' is not one of " + expected);
    fail(*parameter, key, expected);
}

bool CaseSpec::getSwitch(const std::string& key, bool fallback) const {
    return getChoice(key, {"on", "off"}, std::string(fallback ? "on" : "off")) == "on";
}

void CaseSpec::reject(const std::string& key, const std::string& message) const {
    const Parameter* parameter = find(key);
    throw InputError(file, parameter ? parameter->line : line, "case '" + name + "': " + message);
}

void CaseSpec::requireAllKeysUsed() const {
    const std::pair<const std::string, Parameter>* first = nullptr;
    for (const auto& entry : m_parameters) {
        if (!entry.second.used && (!first || entry.second.line < first->second.line)) first = &entry;
    }
    if (!first) return;
    const std::string& key = first->first;

    // Suggest the closest key the lab asked for (or a typed key), if it is close.
    std::vector<std::string> candidates = m_requested;
    for (const CaseKey& typed : caseKeys()) candidates.emplace_back(typed.key);
    std::string suggestion;
    std::size_t bestDistance = std::max<std::size_t>(2, key.size() / 4) + 1;
    for (const std::string& candidate : candidates) {
        const std::size_t distance = editDistance(key, candidate);
        if (distance < bestDistance) {
            bestDistance = distance;
            suggestion = candidate;
        }
    }
    std::string message = "unknown key '" + key + "' in case '" + name + "'";
    if (!suggestion.empty()) message += " (did you mean '" + suggestion + "'?)";
    throw InputError(file, first->second.line, message);
}

void CaseSpec::setParameter(const std::string& key, const std::string& value, int lineOfKey) {
    Parameter& parameter = m_parameters[key];
    parameter.value = value;
    parameter.line = lineOfKey;
    parameter.used = false;
}

const CaseSpec::Parameter* CaseSpec::find(const std::string& key) const {
    const auto found = m_parameters.find(key);
    if (found == m_parameters.end()) {
        if (std::find(m_requested.begin(), m_requested.end(), key) == m_requested.end()) m_requested.push_back(key);
        return nullptr;
    }
    found->second.used = true;
    return &found->second;
}

void CaseSpec::fail(const Parameter& parameter, const std::string& key, const std::string& expected) const {
    throw InputError(file, parameter.line,
                     "expected " + expected + " for '" + key + "', got '" + parameter.value + "'");
}

const CaseSpec* LabManifest::find(const std::string& name) const {
    for (const CaseSpec& spec : cases) {
        if (spec.name == name) return &spec;
    }
    return nullptr;
}

std::string LabManifest::caseNames() const {
    std::string names;
    for (const CaseSpec& spec : cases) {
        if (!names.empty()) names += ", ";
        names += spec.name;
    }
    return names;
}

std::vector<const CaseSpec*> LabManifest::pictureCases() const {
    std::vector<const CaseSpec*> pictures;
    for (const CaseSpec& spec : cases)
        if (spec.check.empty()) pictures.push_back(&spec);
    return pictures;
}

LabManifest parseManifest(const std::string& text, const std::string& file) {
    return ManifestParser(file).parse(text);
}

LabManifest loadManifest(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw InputError(file, 0, "cannot open file: it is a folder, not a case manifest");
    std::ifstream stream(path, std::ios::binary);
    if (!stream) throw InputError(file, 0, "cannot open file");
    std::ostringstream text;
    text << stream.rdbuf();
    return parseManifest(text.str(), file);
}

} // namespace stoa
