#include <stoa/geometry/ObjLoader.hpp>

#include <stoa/core/InputError.hpp>

#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>
#include <unordered_map>

// Loading happens in two passes over the OBJ text.
//
// 1. Our own scan (scanObj) checks what tinyobjloader would accept silently or
//    report without a usable line number: numbers that are malformed, NaN or
//    infinite (it reads them as 0 or keeps them), face indices that point
//    past what is defined so far (it only warns, once, at the end of the
//    file), mtllib files that do not exist and usemtl names that no MTL
//    defines (both only warnings: the faces quietly get a default material).
//    The scan also reads each MTL file, to check its numbers the same way and
//    to know which colours it sets, so that a colour it leaves out keeps the
//    Material default instead of tinyobjloader's black.
// 2. tinyobjloader parses the file for real and triangulates polygons; we
//    then gather its faces into one mesh per material.

namespace stoa {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Calls visit(lineNumber, line, words) for every line of `text` (numbered
/// from 1), with the line split into words at spaces and tabs. Blank lines and
/// whole-line comments are skipped; a comment after other words is left to
/// the caller (tinyobjloader accepts one after "v 1 2 3", not after a face).
template <typename Visit>
void forEachLine(const std::string& text, Visit visit) {
    std::istringstream in(text);
    std::string line;
    int lineNumber = 0;
    std::vector<std::string_view> words;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        words.clear();
        std::string_view rest = line;
        while (!rest.empty()) {
            const std::size_t start = rest.find_first_not_of(" \t");
            if (start == std::string_view::npos) break;
            rest.remove_prefix(start);
            const std::size_t end = std::min(rest.find_first_of(" \t"), rest.size());
            words.push_back(rest.substr(0, end));
            rest.remove_prefix(end);
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
        throw InputError(file, line, "the number '" + std::string(word) +
                                         "' is not finite (NaN, infinite, or too large for a float)");
    }
    if (error != std::errc() || !whole) {
        throw InputError(file, line, "expected a number, found '" + std::string(word) + "'");
    }
    return static_cast<float>(value);
}

/// Checks that words[1..] are between `least` and `most` finite numbers and returns them.
std::vector<float> numbers(const std::vector<std::string_view>& words, std::size_t least, std::size_t most,
                           const char* expected, const std::string& file, int line) {
    const std::size_t count = words.size() - 1;
    if (count < least || count > most) {
        throw InputError(file, line, std::string(words[0]) + " needs " + expected + ", found " + std::to_string(count) +
                                         (count == 1 ? " value" : " values"));
    }
    std::vector<float> values;
    for (std::size_t i = 1; i < words.size(); ++i) values.push_back(finiteNumber(words[i], file, line));
    return values;
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
            throw InputError(file, line, std::string(words[0]) + ": unknown texture option '" + std::string(words[i]) +
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
            throw InputError(file, line, std::string(words[0]) + ": the option " + std::string(words[i]) + " needs " +
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
        throw InputError(file, line, std::string(words[0]) + " names '" + name + "', but " + statement.path.string() +
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
    const std::vector<float> rgb = numbers(words, 1, 3, "a colour (r g b)", file, line);
    if (rgb.size() == 2) throw InputError(file, line, std::string(words[0]) + " needs 1 or 3 numbers, found 2");
    return rgb.size() == 1 ? glm::vec3(rgb[0]) : glm::vec3(rgb[0], rgb[1], rgb[2]);
}

std::vector<MtlEntry> scanMtl(const fs::path& mtlPath, const std::string& text) {
    const std::string file = mtlPath.string();
    const fs::path folder = fs::absolute(mtlPath).parent_path();
    std::vector<MtlEntry> entries;
    forEachLine(text, [&](int line, const std::string& raw, std::vector<std::string_view> words) {
        dropComment(words);
        const std::string_view key = words[0];
        if (key == "newmtl") {
            // As tinyobjloader does: the name is the rest of the line after "newmtl ".
            const std::size_t start = raw.find("newmtl") + 7;
            std::string name = start < raw.size() ? raw.substr(start) : std::string();
            name.erase(name.find_last_not_of(" \t") + 1);
            if (name.empty()) throw InputError(file, line, "newmtl needs a material name");
            entries.push_back({name, folder, {}, {}, {}, {}, {}, {}, {}, {}, 1.0f});
            return;
        }
        MtlEntry* entry = entries.empty() ? nullptr : &entries.back();
        if (key == "map_Kd" || key == "map_Ks" || key == "norm" || key == "map_bump" || key == "map_Bump" ||
            key == "bump") {
            const TextureStatement texture = textureStatement(words, folder, file, line);
            if (!entry) return;  // before any newmtl: tinyobjloader ignores it too
            if (key == "map_Kd") entry->diffuseMap = texture.path.string();
            if (key == "map_Ks") entry->specularMap = texture.path.string();
            if (key == "norm") entry->normalMap = texture.path.string();
            if (key == "map_bump" || key == "map_Bump" || key == "bump") {
                entry->heightMap = texture.path.string();
                entry->bumpScale = texture.bumpMultiplier;
            }
            return;
        }
        if (key != "Ka" && key != "Kd" && key != "Ks" && key != "Ke" && key != "Tf" && key != "Ns" && key != "Ni" &&
            key != "d" && key != "Tr") {
            return;  // other maps, illum and unknown statements: tinyobjloader's business (and unused)
        }
        if (key == "Ka" || key == "Kd" || key == "Ks" || key == "Ke" || key == "Tf") {
            const glm::vec3 colour = mtlColour(words, file, line);
            if (entry && key == "Ka") entry->ambient = colour;
            if (entry && key == "Kd") entry->diffuse = colour;
            if (entry && key == "Ks") entry->specular = colour;
        } else {
            if (key == "d" && words.size() > 1 && words[1] == "-halo") words.erase(words.begin() + 1);
            const float value = numbers(words, 1, 1, "one number", file, line)[0];
            if (entry && key == "Ns") entry->shininess = value;
        }
    });
    return entries;
}

/// What scanObj learned besides "the file is well formed".
struct ObjScan {
    int faceCount = 0;
    std::vector<MtlEntry> materials;                          // from every mtllib, in file order
    std::vector<std::pair<std::string, int>> usedMaterials;  // usemtl name, line
};

/// Checks one face corner "v", "v/vt", "v//vn" or "v/vt/vn" against the
/// counts of positions, uvs and normals defined so far.
void checkCorner(std::string_view corner, int positions, int uvs, int normals, const std::string& file, int line) {
    auto malformed = [&]() {
        std::string message = "expected a face corner like 3, 3/1, 3//2 or 3/1/2, found '" + std::string(corner) + "'";
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
    for (std::size_t i = 0; i < partCount; ++i) {
        if (parts[i].empty()) {
            if (i == 1 && partCount == 3) continue;  // "v//vn" has no uv
            malformed();
        }
        int index = 0;
        const auto [end, error] = std::from_chars(parts[i].data(), parts[i].data() + parts[i].size(), index);
        if (error != std::errc() || end != parts[i].data() + parts[i].size()) malformed();
        if (index == 0) {
            throw InputError(file, line, std::string("face refers to ") + names[i] +
                                             " 0, but OBJ indices start at 1 (or count back from -1)");
        }
        if (std::abs(static_cast<long>(index)) > defined[i]) {
            throw InputError(file, line, std::string("face refers to ") + names[i] + " " + std::to_string(index) +
                                             (index < 0 ? " (counting back)" : "") + " but only " +
                                             std::to_string(defined[i]) + " " + plurals[i] +
                                             " are defined so far");
        }
    }
}

ObjScan scanObj(const fs::path& path, const std::string& text) {
    const std::string file = path.string();
    ObjScan scan;
    int positions = 0, uvs = 0, normals = 0;
    std::set<std::string> loadedMtlFiles;  // each MTL file is read once, as tinyobjloader does

    forEachLine(text, [&](int line, const std::string&, std::vector<std::string_view> words) {
        const std::string_view key = words[0];
        if (key == "f") {
            if (words.size() < 4) {
                throw InputError(file, line,
                                 "a face needs at least 3 corners, found " + std::to_string(words.size() - 1));
            }
            for (std::size_t i = 1; i < words.size(); ++i) checkCorner(words[i], positions, uvs, normals, file, line);
            ++scan.faceCount;
            return;
        }
        dropComment(words);
        if (key == "v") {
            // x y z, optionally w or a colour r g b; tinyobjloader reads 3 or 6.
            numbers(words, 3, 7, "3 numbers (x y z)", file, line);
            ++positions;
        } else if (key == "vt") {
            numbers(words, 1, 3, "1 to 3 numbers (u v)", file, line);
            ++uvs;
        } else if (key == "vn") {
            numbers(words, 3, 3, "3 numbers (x y z)", file, line);
            ++normals;
        } else if (key == "mtllib") {
            // tinyobjloader splits the line at spaces and loads only the first file it finds.
            if (words.size() < 2) throw InputError(file, line, "mtllib needs the name of an MTL file");
            if (words.size() > 2) {
                throw InputError(file, line, "mtllib names " + std::to_string(words.size() - 1) +
                                                 " files; put each MTL file on an mtllib line of its own "
                                                 "(file names cannot contain spaces)");
            }
            const std::string name(words[1]);
            if (loadedMtlFiles.count(name)) return;
            const fs::path mtlPath = path.parent_path() / name;
            const std::optional<std::string> mtlText = readText(mtlPath);
            if (!mtlText) {
                throw InputError(file, line, "mtllib names '" + name + "', but " + mtlPath.string() +
                                                 " does not exist or cannot be read (MTL files are looked for "
                                                 "next to the OBJ file)");
            }
            loadedMtlFiles.insert(name);
            for (MtlEntry& entry : scanMtl(mtlPath, *mtlText)) scan.materials.push_back(std::move(entry));
        } else if (key == "usemtl") {
            if (words.size() < 2) throw InputError(file, line, "usemtl needs a material name");
            const std::string name(words[1]);
            bool defined = false;
            for (const MtlEntry& entry : scan.materials) defined = defined || entry.name == name;
            if (!defined) {
                const std::string reason = loadedMtlFiles.empty() ? "no mtllib line comes before it"
                                                                  : "no MTL file named by an earlier mtllib defines it";
                throw InputError(file, line, "usemtl names material '" + name + "', but " + reason);
            }
            scan.usedMaterials.emplace_back(name, line);
        }
    });
    return scan;
}

/// Turns tinyobjloader's error text into an InputError, taking the line number
/// from it when it names one ("... line 12.)").
InputError tinyobjError(const std::string& file, std::string message) {
    int line = 0;
    std::smatch match;
    if (std::regex_search(message, match, std::regex("line[:]? *([0-9]+)"))) line = std::stoi(match[1]);
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back()))) message.pop_back();
    for (char& c : message) {
        if (c == '\n') c = ' ';
    }
    return InputError(file, line, "tinyobjloader rejected the file: " + message);
}

Material makeMaterial(const tinyobj::material_t& parsed, const std::vector<MtlEntry>& entries) {
    Material material;
    material.name = parsed.name;
    // The first MTL entry of that name, as tinyobjloader keeps the first too.
    for (const MtlEntry& entry : entries) {
        if (entry.name != parsed.name) continue;
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

/// The identity of an OBJ face corner; corners with equal keys become one vertex.
struct CornerKey {
    int position, normal, uv;
    bool operator==(const CornerKey& other) const {
        return position == other.position && normal == other.normal && uv == other.uv;
    }
};

struct CornerKeyHash {
    std::size_t operator()(const CornerKey& key) const {
        std::size_t hash = std::hash<int>()(key.position);
        hash = hash * 1000003u ^ std::hash<int>()(key.normal);
        return hash * 1000003u ^ std::hash<int>()(key.uv);
    }
};

struct PartBuilder {
    ModelPart part;
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> vertexOf;
};

glm::vec3 position(const tinyobj::attrib_t& attrib, std::size_t index) {
    return {attrib.vertices[3 * index], attrib.vertices[3 * index + 1], attrib.vertices[3 * index + 2]};
}

/// The normal the file gives a corner, normalized; nullopt when it gives none
/// (or one of zero length).
std::optional<glm::vec3> fileNormal(const tinyobj::attrib_t& attrib, int index) {
    if (index < 0) return std::nullopt;
    const glm::vec3 normal(attrib.normals[3 * std::size_t(index)], attrib.normals[3 * std::size_t(index) + 1],
                           attrib.normals[3 * std::size_t(index) + 2]);
    const float length = glm::length(normal);
    if (!(length > 1e-20f)) return std::nullopt;
    return normal / length;
}

/// Smooth normals per OBJ position: the positions become the vertices of a
/// mesh whose triangles are all the model's faces, so computeSmoothNormals
/// averages across uv seams and material boundaries, where a surface is
/// still the same surface.
std::vector<glm::vec3> smoothNormalsByPosition(const tinyobj::attrib_t& attrib,
                                               const std::vector<tinyobj::shape_t>& shapes) {
    Mesh positions;
    positions.vertices.resize(attrib.vertices.size() / 3);
    for (std::size_t i = 0; i < positions.vertices.size(); ++i) {
        positions.vertices[i].position = position(attrib, i);
    }
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t offset = 0;
        for (unsigned char cornerCount : shape.mesh.num_face_vertices) {
            for (std::size_t k = 1; k + 1 < cornerCount; ++k) {  // a fan, should a face not be a triangle
                for (std::size_t corner : {offset, offset + k, offset + k + 1}) {
                    positions.indices.push_back(static_cast<std::uint32_t>(shape.mesh.indices[corner].vertex_index));
                }
            }
            offset += cornerCount;
        }
    }
    computeSmoothNormals(positions);
    std::vector<glm::vec3> normals;
    for (const Vertex& vertex : positions.vertices) normals.push_back(vertex.normal);
    return normals;
}

/// Gathers tinyobjloader's triangles into one part per material, in the order
/// the file first uses each material.
std::vector<ModelPart> buildParts(const tinyobj::ObjReader& reader, const std::vector<MtlEntry>& mtlEntries) {
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const std::vector<tinyobj::shape_t>& shapes = reader.GetShapes();
    const std::vector<tinyobj::material_t>& materials = reader.GetMaterials();

    bool anyMissingNormal = false;
    for (const tinyobj::shape_t& shape : shapes) {
        for (const tinyobj::index_t& corner : shape.mesh.indices) {
            anyMissingNormal = anyMissingNormal || !fileNormal(attrib, corner.normal_index);
        }
    }
    const std::vector<glm::vec3> smoothNormals =
        anyMissingNormal ? smoothNormalsByPosition(attrib, shapes) : std::vector<glm::vec3>();

    std::vector<PartBuilder> builders;
    std::map<int, std::size_t> builderOfMaterial;  // tinyobjloader material id (-1 = none) -> index in builders
    auto builderFor = [&](int materialId) -> PartBuilder& {
        if (materialId < 0 || materialId >= static_cast<int>(materials.size())) materialId = -1;
        const auto found = builderOfMaterial.find(materialId);
        if (found != builderOfMaterial.end()) return builders[found->second];
        builderOfMaterial.emplace(materialId, builders.size());
        builders.emplace_back();
        if (materialId >= 0) {
            builders.back().part.material = makeMaterial(materials[std::size_t(materialId)], mtlEntries);
        }
        return builders.back();
    };

    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t offset = 0;
        for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
            const int materialId = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
            PartBuilder& builder = builderFor(materialId);
            auto vertexFor = [&](const tinyobj::index_t& corner) {
                const CornerKey key{corner.vertex_index, corner.normal_index, corner.texcoord_index};
                const auto existing = builder.vertexOf.find(key);
                if (existing != builder.vertexOf.end()) return existing->second;
                Vertex vertex;
                const std::size_t p = std::size_t(corner.vertex_index);
                vertex.position = position(attrib, p);
                const std::optional<glm::vec3> normal = fileNormal(attrib, corner.normal_index);
                vertex.normal = normal ? *normal : smoothNormals[p];  // computed when any normal is missing
                if (corner.texcoord_index >= 0) {
                    const std::size_t t = std::size_t(corner.texcoord_index);
                    vertex.uv = {attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]};
                }
                const auto index = static_cast<std::uint32_t>(builder.part.mesh.vertices.size());
                builder.part.mesh.vertices.push_back(vertex);
                builder.vertexOf.emplace(key, index);
                return index;
            };
            const std::size_t cornerCount = shape.mesh.num_face_vertices[face];
            for (std::size_t k = 1; k + 1 < cornerCount; ++k) {  // tinyobjloader gives triangles; a fan otherwise
                for (std::size_t corner : {offset, offset + k, offset + k + 1}) {
                    builder.part.mesh.indices.push_back(vertexFor(shape.mesh.indices[corner]));
                }
            }
            offset += cornerCount;
        }
    }

    std::vector<ModelPart> parts;
    for (PartBuilder& builder : builders) {
        if (!builder.part.mesh.indices.empty()) parts.push_back(std::move(builder.part));
    }
    return parts;
}

} // namespace

Model loadObj(const fs::path& path) {
    const std::string file = path.string();
    std::error_code error;
    if (!fs::exists(path, error)) throw InputError(file, 0, "the file does not exist");
    if (fs::is_directory(path, error)) throw InputError(file, 0, "this is a folder, not an OBJ file");
    const std::optional<std::string> text = readText(path);
    if (!text) throw InputError(file, 0, "the file cannot be read");

    const ObjScan scan = scanObj(path, *text);
    if (scan.faceCount == 0) throw InputError(file, 0, "the file has no faces (f lines), so there is nothing to draw");

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = path.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file, config) || !reader.Error().empty()) throw tinyobjError(file, reader.Error());

    // The scan saw every usemtl name defined; make sure tinyobjloader loaded it too.
    for (const auto& [name, line] : scan.usedMaterials) {
        bool loaded = false;
        for (const tinyobj::material_t& material : reader.GetMaterials()) loaded = loaded || material.name == name;
        if (!loaded) throw InputError(file, line, "material '" + name + "' could not be loaded from its MTL file");
    }

    Model model;
    model.source = file;
    model.parts = buildParts(reader, scan.materials);
    if (model.parts.empty()) throw InputError(file, 0, "tinyobjloader found no faces in the file");
    for (const ModelPart& part : model.parts) part.mesh.validate(file);
    return model;
}

} // namespace stoa
