#include <stoa/geometry/ObjLoader.hpp>

#include "FaceTriangulation.hpp"

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

// One pass over the OBJ text reads and checks every line (tinyobjloader used
// to parse it a second time; it could not be made to refuse what this loader
// refuses, triangulated large polygons in quadratic time, counted corners in
// an unsigned char, and allocated what a `t` line asked for): positions, uvs
// and normals into arrays, faces into triangles of the part of their
// material. MTL files are read the same way. Then the triangles' corners
// become vertices, one per distinct (position, normal, uv).

namespace stoa {

namespace fs = std::filesystem;

using detail::Corner;
using detail::CornerHash;
using detail::triangulate;

namespace {

std::string excerpt(std::string_view word) { return quoteInput(std::string(word)); }

/// The text of an OBJ or MTL file: no UTF-16, no UTF-8 byte-order mark.
std::string_view checkedText(const std::string& text, const std::string& file) {
    const bool utf16Mark = text.size() >= 2 && ((static_cast<unsigned char>(text[0]) == 0xFF &&
                                                  static_cast<unsigned char>(text[1]) == 0xFE) ||
                                                 (static_cast<unsigned char>(text[0]) == 0xFE &&
                                                  static_cast<unsigned char>(text[1]) == 0xFF));
    // Without a mark, UTF-16 text shows as a NUL byte next to every ASCII letter of its first characters.
    const bool utf16Zeros = text.size() >= 4 && (text[0] == '\0' || text[1] == '\0') && (text[2] == '\0' || text[3] == '\0');
    if (utf16Mark || utf16Zeros) throw InputError(file, 0, "UTF-16 is not supported; save the file as UTF-8");
    std::string_view view = text;
    if (view.substr(0, 3) == "\xEF\xBB\xBF") view.remove_prefix(3);  // a UTF-8 byte-order mark
    return view;
}

/// Calls visit(lineNumber, line, words) for every line of `text` (numbered
/// from 1; lines end at LF, CR LF or a lone CR), with the line split into
/// words at spaces and tabs. Blank lines and whole-line comments are skipped;
/// a comment after other words is left to the caller.
template <typename Visit>
void forEachLine(std::string_view text, Visit visit) {
    int lineNumber = 0;
    std::vector<std::string_view> words;
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = at;
        while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
        const std::string_view line = text.substr(at, end - at);
        at = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
        ++lineNumber;
        words.clear();
        for (std::size_t i = 0; i < line.size();) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
            const std::size_t start = i;
            while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
            if (i > start) words.push_back(line.substr(start, i - start));
        }
        if (words.empty() || words.front().front() == '#') continue;
        visit(lineNumber, line, words);
    }
}

/// Drops a trailing comment ("v 1 2 3 # top corner").
void dropComment(std::vector<std::string_view>& words) {
    for (std::size_t i = 1; i < words.size(); ++i) {
        if (words[i].front() == '#') {
            words.resize(i);
            return;
        }
    }
}

/// The rest of `line` after its first word, without surrounding blanks: a
/// name that may hold spaces ("newmtl old wood", "usemtl old wood").
std::string restOfLine(std::string_view line, std::string_view key) {
    std::size_t start = line.find(key) + key.size();
    while (start < line.size() && (line[start] == ' ' || line[start] == '\t')) ++start;
    std::size_t end = line.size();
    while (end > start && (line[end - 1] == ' ' || line[end - 1] == '\t')) --end;
    return std::string(line.substr(start, end - start));
}

/// Reads `word` as a finite number, or throws InputError(file, line, ...).
/// std::from_chars ignores the locale, unlike strtod.
float finiteNumber(std::string_view word, const std::string& file, int line) {
    std::string_view digits = word;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const bool whole = end == digits.data() + digits.size();
    if (error == std::errc::result_out_of_range && whole) {
        // Too small ("1e-999") reads as 0; too large ("1e999") is an error below.
        const std::size_t exponent = digits.find_first_of("eE");
        if (exponent != std::string_view::npos && digits.substr(exponent + 1, 1) == "-") return 0.0f;
    }
    if ((error == std::errc::result_out_of_range && whole) ||
        (error == std::errc() && whole && !std::isfinite(static_cast<float>(value)))) {
        throw InputError(file, line, "the number '" + excerpt(word) +
                                         "' is not finite (NaN, infinite, or too large for a float)");
    }
    if (error != std::errc() || !whole) {
        throw InputError(file, line, "expected a number, found '" + excerpt(word) + "'");
    }
    return static_cast<float>(value);
}

/// Checks that words[1..] are between `least` and `most` finite numbers and
/// writes them to `values` (which holds `most`); returns their count.
std::size_t numbers(const std::vector<std::string_view>& words, std::size_t least, std::size_t most,
                    const char* expected, const std::string& file, int line, float* values) {
    const std::size_t count = words.size() - 1;
    if (count < least || count > most) {
        throw InputError(file, line, std::string(words[0]) + " needs " + expected + ", found " + std::to_string(count) +
                                         (count == 1 ? " value" : " values"));
    }
    for (std::size_t i = 1; i < words.size(); ++i) values[i - 1] = finiteNumber(words[i], file, line);
    return count;
}

/// What our own read of an MTL file found for one material: the colours the
/// file sets (absent = keep the Material default) and where it lives.
struct MtlEntry {
    std::string name;
    fs::path folder;  // absolute folder of the MTL file, for its texture paths
    std::optional<glm::vec3> ambient, diffuse, specular;
    std::optional<float> shininess;
    std::string diffuseMap, specularMap, normalMap, heightMap;  // absolute paths; empty = none
    float bumpScale = 1.0f;
};

/// A texture name as written in an MTL file, made an absolute path relative
/// to the MTL file's folder (backslashes, from files written on Windows, become slashes).
fs::path resolveTexture(std::string name, const fs::path& folder) {
    for (char& c : name) {
        if (c == '\\') c = '/';
    }
    return (folder / name).lexically_normal();
}

/// The texture named by a map statement ("map_Kd -o 0.5 0.5 wood.png") and its
/// -bm option. The options are those of the MTL specification; each is checked
/// for its count of values, so that a value is never taken for the file name.
struct TextureStatement {
    fs::path path;           // absolute; the file exists
    float bumpMultiplier = 1.0f;
};

TextureStatement textureStatement(const std::vector<std::string_view>& words, const fs::path& folder,
                                  const std::string& file, int line) {
    // Option -> (fewest, most) values it takes.
    static const std::map<std::string_view, std::pair<int, int>> options = {
        {"-blendu", {1, 1}}, {"-blendv", {1, 1}}, {"-bm", {1, 1}},      {"-boost", {1, 1}}, {"-cc", {1, 1}},
        {"-clamp", {1, 1}},  {"-imfchan", {1, 1}}, {"-mm", {2, 2}},     {"-o", {1, 3}},     {"-s", {1, 3}},
        {"-t", {1, 3}},      {"-texres", {1, 1}},  {"-type", {1, 1}}};
    auto isNumber = [](std::string_view word) {
        double ignored = 0.0;
        if (!word.empty() && word.front() == '+') word.remove_prefix(1);
        const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), ignored);
        return error == std::errc() && end == word.data() + word.size();
    };
    TextureStatement statement;
    std::size_t i = 1;
    while (i < words.size() && words[i].size() > 1 && words[i].front() == '-' && !isNumber(words[i])) {
        const auto option = options.find(words[i]);
        if (option == options.end()) {
            throw InputError(file, line, std::string(words[0]) + ": unknown texture option '" + excerpt(words[i]) +
                                             "' (expected one of -blendu -blendv -bm -boost -cc -clamp -imfchan "
                                             "-mm -o -s -t -texres -type, then the file name)");
        }
        const auto [fewest, most] = option->second;
        std::size_t values = 0;
        while (static_cast<int>(values) < most && i + 1 + values < words.size() &&
               (static_cast<int>(values) < fewest || isNumber(words[i + 1 + values]))) {
            ++values;
        }
        if (static_cast<int>(values) < fewest) {
            throw InputError(file, line, std::string(words[0]) + ": the option " + excerpt(words[i]) + " needs " +
                                             std::to_string(fewest) + (fewest == 1 ? " value" : " values"));
        }
        if (words[i] == "-bm") statement.bumpMultiplier = finiteNumber(words[i + 1], file, line);
        i += 1 + values;
    }
    if (i == words.size()) throw InputError(file, line, std::string(words[0]) + " needs the name of a texture file");
    std::string name(words[i]);
    for (++i; i < words.size(); ++i) name += " " + std::string(words[i]);  // a name with spaces
    statement.path = resolveTexture(name, folder);
    std::error_code error;
    if (!fs::is_regular_file(statement.path, error)) {
        throw InputError(file, line, std::string(words[0]) + " names '" + quoteInput(name) + "', but " + quoteInput(statement.path.string(), 200) +
                                         " does not exist or is not a file (texture paths are relative to the "
                                         "MTL file's folder)");
    }
    return statement;
}

/// An MTL colour: "Kd r g b", or "Kd r" meaning grey (the MTL spec's
/// shorthand, which tinyobjloader reads as (r, 0, 0)). The "spectral" and
/// "xyz" forms are not supported.
glm::vec3 mtlColour(const std::vector<std::string_view>& words, const std::string& file, int line) {
    if (words.size() > 1 && (words[1] == "spectral" || words[1] == "xyz")) {
        throw InputError(file, line, std::string(words[0]) + " " + std::string(words[1]) +
                                         " is not supported; give the colour as r g b in [0, 1]");
    }
    float rgb[3];
    const std::size_t count = numbers(words, 1, 3, "a colour (r g b)", file, line, rgb);
    if (count == 2) throw InputError(file, line, std::string(words[0]) + " needs 1 or 3 numbers, found 2");
    return count == 1 ? glm::vec3(rgb[0]) : glm::vec3(rgb[0], rgb[1], rgb[2]);
}

/// A colour clamped to [0, 1], with a warning naming the line when it was outside.
glm::vec3 clampedColour(glm::vec3 colour, std::string_view key, const std::string& file, int line,
                        std::ostream& warnings) {
    const glm::vec3 clamped = glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
    if (clamped != colour) {
        warnings << "stoa: warning: " << file << ":" << line << ": " << key << " (" << colour.x << ", " << colour.y
                 << ", " << colour.z << ") is outside [0, 1]; clamped to (" << clamped.x << ", " << clamped.y << ", "
                 << clamped.z << ")\n";
    }
    return clamped;
}

std::vector<MtlEntry> scanMtl(const fs::path& mtlPath, const std::string& text, std::ostream& warnings) {
    const std::string file = mtlPath.string();
    std::error_code ignored;
    const fs::path absolute = fs::absolute(mtlPath, ignored);
    const fs::path folder = (absolute.empty() ? mtlPath : absolute).parent_path();
    std::vector<MtlEntry> entries;
    forEachLine(checkedText(text, file), [&](int line, std::string_view raw, std::vector<std::string_view>& words) {
        dropComment(words);
        const std::string_view key = words[0];
        if (key == "newmtl") {
            // The name is the rest of the line: exporters write names with spaces.
            std::string name = restOfLine(raw, "newmtl");
            if (name.empty()) throw InputError(file, line, "newmtl needs a material name");
            entries.push_back({name, folder, {}, {}, {}, {}, {}, {}, {}, {}, 1.0f});
            return;
        }
        MtlEntry* entry = entries.empty() ? nullptr : &entries.back();
        if (key == "map_Kd" || key == "map_Ks" || key == "norm" || key == "map_bump" || key == "map_Bump" ||
            key == "bump") {
            const TextureStatement texture = textureStatement(words, folder, file, line);
            if (!entry) return;  // before any newmtl: no material to attach it to
            if (key == "map_Kd") entry->diffuseMap = texture.path.string();
            if (key == "map_Ks") entry->specularMap = texture.path.string();
            if (key == "norm") entry->normalMap = texture.path.string();
            if (key == "map_bump" || key == "map_Bump" || key == "bump") {
                entry->heightMap = texture.path.string();
                entry->bumpScale = texture.bumpMultiplier;
            }
            return;
        }
        if (key == "Ka" || key == "Kd" || key == "Ks" || key == "Ke" || key == "Tf") {
            const glm::vec3 colour = mtlColour(words, file, line);
            if (!entry) return;
            if (key == "Ka") entry->ambient = clampedColour(colour, key, file, line, warnings);
            if (key == "Kd") entry->diffuse = clampedColour(colour, key, file, line, warnings);
            if (key == "Ks") entry->specular = clampedColour(colour, key, file, line, warnings);
        } else if (key == "Ns" || key == "Ni" || key == "d" || key == "Tr") {
            if (key == "d" && words.size() > 1 && words[1] == "-halo") words.erase(words.begin() + 1);
            float value = 0.0f;
            numbers(words, 1, 1, "one number", file, line, &value);
            if (entry && key == "Ns") {
                if (value < 0.0f) {
                    warnings << "stoa: warning: " << file << ":" << line << ": Ns " << value
                             << " is negative; a Blinn-Phong exponent must be >= 0, clamped to 0\n";
                    value = 0.0f;
                }
                entry->shininess = value;
            }
        }
        // Other maps, illum and unknown statements are not used.
    });
    return entries;
}

/// The triangles of one material while the file is read.
struct PartTriangles {
    std::string material;  // empty: no usemtl (Material{})
    std::vector<Corner> corners;  // 3 per triangle
};

/// Reads one face corner "v", "v/vt", "v//vn" or "v/vt/vn", checked against
/// the counts of positions, uvs and normals defined so far.
Corner readCorner(std::string_view corner, int positions, int uvs, int normals, const std::string& file, int line) {
    auto malformed = [&]() {
        std::string message = "expected a face corner like 3, 3/1, 3//2 or 3/1/2, found '" + excerpt(corner) + "'";
        if (corner.front() == '#') message += " (comments must be on a line of their own after f)";
        throw InputError(file, line, message);
    };
    std::string_view parts[3];
    std::size_t partCount = 0;
    for (std::string_view rest = corner;;) {
        if (partCount == 3) malformed();
        const std::size_t slash = rest.find('/');
        parts[partCount++] = rest.substr(0, slash);
        if (slash == std::string_view::npos) break;
        rest.remove_prefix(slash + 1);
    }
    const char* names[3] = {"vertex", "texture coordinate", "normal"};
    const char* plurals[3] = {"vertices (v)", "texture coordinates (vt)", "normals (vn)"};
    const int defined[3] = {positions, uvs, normals};
    int resolved[3] = {-1, -1, -1};
    for (std::size_t i = 0; i < partCount; ++i) {
        if (parts[i].empty()) {
            if (i == 1 && partCount == 3) continue;  // "v//vn" has no uv
            malformed();
        }
        std::string_view digits = parts[i];
        if (digits.front() == '+') digits.remove_prefix(1);
        long long index = 0;
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
        if (end != digits.data() + digits.size() || (error != std::errc() && error != std::errc::result_out_of_range)) {
            malformed();
        }
        if (error == std::errc::result_out_of_range) index = digits.front() == '-' ? -(1LL << 62) : (1LL << 62);
        if (index == 0) {
            throw InputError(file, line, std::string("face refers to ") + names[i] +
                                             " 0, but OBJ indices start at 1 (or count back from -1)");
        }
        if (index > defined[i] || index < -static_cast<long long>(defined[i])) {
            throw InputError(file, line, std::string("face refers to ") + names[i] + " " + excerpt(parts[i]) +
                                             (index < 0 ? " (counting back)" : "") + " but only " +
                                             std::to_string(defined[i]) + " " + plurals[i] +
                                             " are defined so far");
        }
        resolved[i] = static_cast<int>(index > 0 ? index - 1 : defined[i] + index);
    }
    return {resolved[0], resolved[1], resolved[2]};
}

Material makeMaterial(const std::string& name, const std::vector<MtlEntry>& entries) {
    Material material;
    if (name.empty()) return material;
    material.name = name;
    // The first MTL entry of that name.
    for (const MtlEntry& entry : entries) {
        if (entry.name != name) continue;
        if (entry.ambient) material.ambient = *entry.ambient;
        if (entry.diffuse) material.diffuse = *entry.diffuse;
        if (entry.specular) material.specular = *entry.specular;
        if (entry.shininess) material.shininess = *entry.shininess;
        material.diffuseMap = entry.diffuseMap;
        material.specularMap = entry.specularMap;
        material.normalMap = entry.normalMap;
        material.heightMap = entry.heightMap;
        material.bumpScale = entry.bumpScale;
        break;
    }
    return material;
}

/// What the read of an OBJ file gathered.
struct ObjData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec3> normals;    // unit length, or zero where the file's normal is (0, 0, 0)
    std::vector<PartTriangles> parts;  // in the order the file first uses each material
    std::vector<MtlEntry> materials;   // from every mtllib, in file order
    int faces = 0;
    int lines = 0;
};

/// The state of one OBJ file's read, a statement at a time.
class ObjReader {
public:
    ObjReader(const fs::path& path, const MtlReader& readMtl, std::ostream& warnings)
        : m_path(path), m_file(path.string()), m_readMtl(readMtl), m_warnings(warnings) {}

    void statement(int line, std::string_view raw, std::vector<std::string_view>& words) {
        m_data.lines = line;
        const std::string_view key = words[0];
        if (key == "f") return face(line, words);
        dropComment(words);
        if (key == "v" || key == "vt" || key == "vn") {
            vertexData(key, line, words);
        } else if (key == "l" || key == "p") {
            // Lines and points are not drawn, but their indices are checked like a face's.
            for (std::size_t i = 1; i < words.size(); ++i) (void)corner(words[i], line);
        } else if (key == "mtllib") {
            mtllib(line, words);
        } else if (key == "usemtl") {
            usemtl(line, raw);
        }
        // o, g, s, mg and statements Stoa does not use are skipped.
    }

    ObjData take() { return std::move(m_data); }

private:
    Corner corner(std::string_view word, int line) const {
        return readCorner(word, static_cast<int>(m_data.positions.size()), static_cast<int>(m_data.uvs.size()),
                          static_cast<int>(m_data.normals.size()), m_file, line);
    }

    void face(int line, const std::vector<std::string_view>& words) {
        if (words.size() < 4)
            throw InputError(m_file, line, "a face needs at least 3 corners, found " + std::to_string(words.size() - 1));
        m_face.clear();
        for (std::size_t i = 1; i < words.size(); ++i) m_face.push_back(corner(words[i], line));
        if (!m_part) {
            const auto found = m_partOf.find(m_material);
            if (found == m_partOf.end()) {
                m_partOf.emplace(m_material, m_data.parts.size());
                m_data.parts.push_back({m_material, {}});
                m_part = &m_data.parts.back();
            } else {
                m_part = &m_data.parts[found->second];
            }
        }
        triangulate(m_face, m_data.positions, m_part->corners, m_file, line);
        ++m_data.faces;
    }

    void vertexData(std::string_view key, int line, const std::vector<std::string_view>& words) {
        float values[7];
        if (key == "v") {
            // x y z, optionally w or a colour r g b.
            numbers(words, 3, 7, "3 numbers (x y z)", m_file, line, values);
            m_data.positions.emplace_back(values[0], values[1], values[2]);
        } else if (key == "vt") {
            const std::size_t count = numbers(words, 1, 3, "1 to 3 numbers (u v)", m_file, line, values);
            m_data.uvs.emplace_back(values[0], count > 1 ? values[1] : 0.0f);
        } else {
            numbers(words, 3, 3, "3 numbers (x y z)", m_file, line, values);
            // Divided by its largest component first, so that "vn 3e38 3e38 3e38"
            // (whose length overflows a float) still gives a unit normal.
            glm::vec3 normal(values[0], values[1], values[2]);
            const float largest = std::max({std::abs(normal.x), std::abs(normal.y), std::abs(normal.z)});
            m_data.normals.push_back(largest > 0.0f ? glm::normalize(normal / largest) : glm::vec3(0.0f));
        }
    }

    void mtllib(int line, const std::vector<std::string_view>& words) {
        if (words.size() < 2) throw InputError(m_file, line, "mtllib needs the name of an MTL file");
        if (words.size() > 2) {
            throw InputError(m_file, line, "mtllib names " + std::to_string(words.size() - 1) +
                                               " files; put each MTL file on an mtllib line of its own "
                                               "(file names cannot contain spaces)");
        }
        const std::string name(words[1]);
        if (m_loadedMtlFiles.count(name)) return;
        const fs::path mtlPath = m_path.parent_path() / name;
        std::string mtlText;
        try {
            mtlText = m_readMtl(mtlPath);
        } catch (const InputError& error) {
            throw InputError(m_file, line, "mtllib names '" + excerpt(name) + "', but " +
                                               quoteInput(mtlPath.string(), 200) + ": " + error.message() +
                                               " (MTL files are looked for next to the OBJ file)");
        }
        m_loadedMtlFiles.insert(name);
        for (MtlEntry& entry : scanMtl(mtlPath, mtlText, m_warnings)) m_data.materials.push_back(std::move(entry));
    }

    void usemtl(int line, std::string_view raw) {
        std::string name = restOfLine(raw, "usemtl");
        if (name.empty()) throw InputError(m_file, line, "usemtl needs a material name");
        bool defined = false;
        for (const MtlEntry& entry : m_data.materials) defined = defined || entry.name == name;
        if (!defined) {
            const std::string reason = m_loadedMtlFiles.empty() ? "no mtllib line comes before it"
                                                                : "no MTL file named by an earlier mtllib defines it";
            throw InputError(m_file, line, "usemtl names material '" + quoteInput(name) + "', but " + reason);
        }
        if (name != m_material) {
            m_material = std::move(name);
            m_part = nullptr;
        }
    }

    const fs::path& m_path;
    const std::string m_file;
    const MtlReader& m_readMtl;
    std::ostream& m_warnings;
    ObjData m_data;
    std::set<std::string> m_loadedMtlFiles;   // each MTL file is read once
    std::string m_material;                   // the current usemtl name; empty = none
    std::map<std::string, std::size_t> m_partOf;
    PartTriangles* m_part = nullptr;          // the part of `m_material`, made at its first face
    std::vector<Corner> m_face;
};

ObjData readObj(const std::string& text, const fs::path& path, const MtlReader& readMtl, std::ostream& warnings) {
    ObjReader reader(path, readMtl, warnings);
    forEachLine(checkedText(text, path.string()),
                [&](int line, std::string_view raw, std::vector<std::string_view>& words) {
                    reader.statement(line, raw, words);
                });
    return reader.take();
}

/// Smooth normals per OBJ position: the positions become the vertices of a
/// mesh whose triangles are all the model's faces, so computeSmoothNormals
/// averages across uv seams and material boundaries, where a surface is
/// still the same surface.
std::vector<glm::vec3> smoothNormalsByPosition(const ObjData& data) {
    Mesh positions;
    positions.vertices.resize(data.positions.size());
    for (std::size_t i = 0; i < positions.vertices.size(); ++i) positions.vertices[i].position = data.positions[i];
    for (const PartTriangles& part : data.parts) {
        for (const Corner& corner : part.corners) positions.indices.push_back(static_cast<std::uint32_t>(corner.position));
    }
    computeSmoothNormals(positions);
    std::vector<glm::vec3> normals;
    normals.reserve(positions.vertices.size());
    for (const Vertex& vertex : positions.vertices) normals.push_back(vertex.normal);
    return normals;
}

Model buildModel(const ObjData& data, const std::string& file) {
    auto hasNormal = [&](const Corner& corner) {
        return corner.normal >= 0 && data.normals[std::size_t(corner.normal)] != glm::vec3(0.0f);
    };
    bool anyMissingNormal = false;
    for (const PartTriangles& part : data.parts) {
        for (const Corner& corner : part.corners) anyMissingNormal = anyMissingNormal || !hasNormal(corner);
    }
    const std::vector<glm::vec3> smoothNormals = anyMissingNormal ? smoothNormalsByPosition(data) : std::vector<glm::vec3>();

    Model model;
    model.source = file;
    for (const PartTriangles& triangles : data.parts) {
        if (triangles.corners.empty()) continue;
        ModelPart part;
        part.material = makeMaterial(triangles.material, data.materials);
        std::unordered_map<Corner, std::uint32_t, CornerHash> vertexOf;
        part.mesh.indices.reserve(triangles.corners.size());
        for (const Corner& corner : triangles.corners) {
            const auto existing = vertexOf.find(corner);
            if (existing != vertexOf.end()) {
                part.mesh.indices.push_back(existing->second);
                continue;
            }
            Vertex vertex;
            vertex.position = data.positions[std::size_t(corner.position)];
            vertex.normal = hasNormal(corner) ? data.normals[std::size_t(corner.normal)]
                                              : smoothNormals[std::size_t(corner.position)];
            if (corner.uv >= 0) vertex.uv = data.uvs[std::size_t(corner.uv)];
            const auto index = static_cast<std::uint32_t>(part.mesh.vertices.size());
            part.mesh.vertices.push_back(vertex);
            vertexOf.emplace(corner, index);
            part.mesh.indices.push_back(index);
        }
        model.parts.push_back(std::move(part));
    }
    return model;
}

} // namespace

Model parseObj(const std::string& text, const fs::path& path, const MtlReader& readMtl, std::ostream& warnings) {
    const std::string file = path.string();
    const ObjData data = readObj(text, path, readMtl, warnings);
    if (data.faces == 0) {
        throw InputError(file, 0, "the file has no faces: none of its " + std::to_string(data.lines) +
                                      " lines is an f line, so there is nothing to draw");
    }
    Model model = buildModel(data, file);
    for (const ModelPart& part : model.parts) part.mesh.validate(file);
    return model;
}

Model loadObj(const fs::path& path, std::ostream& warnings) {
    const std::string text = readInputFile(path, maxObjFileBytes, "an OBJ file");
    const MtlReader readMtl = [](const fs::path& mtlPath) {
        return readInputFile(mtlPath, maxMtlFileBytes, "an MTL file");
    };
    return parseObj(text, path, readMtl, warnings);
}

Model loadObj(const fs::path& path) { return loadObj(path, std::cerr); }

} // namespace stoa
