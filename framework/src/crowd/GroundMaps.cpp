#include <stoa/crowd/GroundMaps.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/core/InputFile.hpp>
#include <stoa/image/Image.hpp>

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <memory>
#include <string>

namespace stoa {

namespace {

GroundGrid gridOf(const GroundDescription& ground, int width, int height) {
    GroundGrid grid;
    grid.width = width;
    grid.height = height;
    grid.footprintMin = ground.footprintMin;
    grid.footprintMax = ground.footprintMax;
    return grid;
}

void requireSize(int width, int height, const std::filesystem::path& map, const std::filesystem::path& worldFile,
                 int line) {
    if (width < 2 || height < 2) {
        throw InputError(worldFile.string(), line,
                         "the map " + map.string() + " is " + std::to_string(width) + " x " +
                             std::to_string(height) + " texels; a ground map needs at least 2 x 2");
    }
}

/// The samples of a 16-bit PGM (P5 binary, big-endian; or P2 text) scaled by
/// its maxval to [0, 1]. Image::bitsPerChannel() has checked the header and the
/// size limits; the samples are read here because stb_image copies a 16-bit
/// PNM's big-endian bytes without swapping them and does not scale by maxval.
std::vector<float> readPgm16(const std::string& bytes, const std::filesystem::path& path, int& width, int& height) {
    std::size_t at = 2;
    const auto number = [&](const char* what) {
        for (;;) {   // whitespace and comments
            while (at < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
            if (at < bytes.size() && bytes[at] == '#') {
                while (at < bytes.size() && bytes[at] != '\n') ++at;
                continue;
            }
            break;
        }
        long value = 0;
        std::size_t digits = 0;
        while (at < bytes.size() && std::isdigit(static_cast<unsigned char>(bytes[at])) && digits < 9) {
            value = value * 10 + (bytes[at++] - '0');
            ++digits;
        }
        if (digits == 0) throw InputError(path.string(), 0, std::string("expected ") + what + " in the 16-bit PGM");
        return value;
    };
    const bool binary = bytes.compare(0, 2, "P5") == 0;
    width = static_cast<int>(number("the width"));
    height = static_cast<int>(number("the height"));
    const long maxval = number("the maximum value");
    if (maxval < 256 || maxval > 65535)
        throw InputError(path.string(), 0, "a 16-bit PGM's maximum value must be 256..65535, not " + std::to_string(maxval));
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::vector<float> values(count);
    if (binary) {
        ++at;   // the one whitespace byte after maxval
        if (bytes.size() < at || bytes.size() - at < count * 2) {
            throw InputError(path.string(), 0, "the 16-bit PGM holds " + std::to_string((bytes.size() - std::min(at, bytes.size())) / 2) +
                                                   " samples; its header promises " + std::to_string(count));
        }
        for (std::size_t i = 0; i < count; ++i) {
            const unsigned sample = (static_cast<unsigned char>(bytes[at + 2 * i]) << 8u) |
                                    static_cast<unsigned char>(bytes[at + 2 * i + 1]);
            if (sample > static_cast<unsigned long>(maxval))
                throw InputError(path.string(), 0, "sample " + std::to_string(i) + " of the 16-bit PGM is " +
                                                       std::to_string(sample) + ", above its maximum " + std::to_string(maxval));
            values[i] = static_cast<float>(sample) / static_cast<float>(maxval);
        }
    } else {
        for (std::size_t i = 0; i < count; ++i) {
            const long sample = number("a sample");
            if (sample > maxval)
                throw InputError(path.string(), 0, "sample " + std::to_string(i) + " of the 16-bit PGM is " +
                                                       std::to_string(sample) + ", above its maximum " + std::to_string(maxval));
            values[i] = static_cast<float>(sample) / static_cast<float>(maxval);
        }
    }
    return values;
}

/// Grey values in [0, 1] of an 8-bit image (colour as luminance) or a 16-bit grey one.
std::vector<float> readGrey(const std::filesystem::path& path, int& width, int& height) {
    const std::string bytes = readInputFile(path, Image::maxFileBytes, "height map");
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    std::vector<float> values;
    if (Image::bitsPerChannel(data, bytes.size(), path.string()) == 16) {
        if (bytes.compare(0, 2, "P5") == 0 || bytes.compare(0, 2, "P2") == 0) return readPgm16(bytes, path, width, height);
        // A 16-bit PNG; bitsPerChannel() has checked the header and the size limits.
        int channels = 0;
        std::unique_ptr<stbi_us, void (*)(void*)> pixels(
            stbi_load_16_from_memory(data, static_cast<int>(bytes.size()), &width, &height, &channels, 1),
            stbi_image_free);
        if (!pixels) {
            throw InputError(path.string(), 0, std::string("cannot decode the 16-bit height map: ") +
                                                   (stbi_failure_reason() ? stbi_failure_reason() : "unknown"));
        }
        values.resize(static_cast<std::size_t>(width) * height);
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = pixels.get()[i] / 65535.0f;
        return values;
    }
    const Image image = Image::decode(data, bytes.size(), path.string(), 1);
    width = image.width();
    height = image.height();
    values.resize(static_cast<std::size_t>(width) * height);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = image.data()[i] / 255.0f;
    return values;
}

} // namespace

GroundMaps loadGroundMaps(const GroundDescription& ground, const std::filesystem::path& worldFile) {
    GroundMaps maps;
    const Image collision = Image::load(ground.collisionMap, 1);
    requireSize(collision.width(), collision.height(), ground.collisionMap, worldFile, ground.line);
    maps.collision.grid = gridOf(ground, collision.width(), collision.height());
    maps.collision.walkable.resize(static_cast<std::size_t>(collision.width()) * collision.height());
    for (std::size_t i = 0; i < maps.collision.walkable.size(); ++i)
        maps.collision.walkable[i] = collision.data()[i] >= 128 ? 1 : 0;

    maps.heights.heightMin = ground.heightMin;
    maps.heights.heightMax = ground.heightMax;
    if (ground.heightMap.empty()) {
        maps.heights.grid = gridOf(ground, 1, 1);
        maps.heights.values = {0.0f};
        return maps;
    }
    int width = 0, height = 0;
    maps.heights.values = readGrey(ground.heightMap, width, height);
    requireSize(width, height, ground.heightMap, worldFile, ground.line);
    maps.heights.grid = gridOf(ground, width, height);
    return maps;
}

GroundMaps flatGround(glm::vec2 footprintMin, glm::vec2 footprintMax, int texels) {
    GroundMaps maps;
    maps.collision.grid = {texels, texels, footprintMin, footprintMax};
    maps.collision.walkable.assign(static_cast<std::size_t>(texels) * texels, 1);
    maps.heights.grid = {1, 1, footprintMin, footprintMax};
    maps.heights.values = {0.0f};
    return maps;
}

Mesh terrainMesh(const HeightField& field, float uvMetres) {
    const GroundGrid& grid = field.grid;
    const glm::vec2 size = grid.footprintMax - grid.footprintMin;
    const glm::vec2 cell = size / glm::vec2(grid.width, grid.height);
    Mesh mesh;
    if (grid.width < 2 || grid.height < 2) {
        // A flat ground: one quad over the footprint.
        const float y = field.heightMin;
        const glm::vec2 a = grid.footprintMin, b = grid.footprintMax;
        for (const glm::vec2 corner : {glm::vec2(a.x, a.y), glm::vec2(a.x, b.y), glm::vec2(b.x, b.y), glm::vec2(b.x, a.y)}) {
            Vertex vertex;
            vertex.position = {corner.x, y, corner.y};
            vertex.normal = {0.0f, 1.0f, 0.0f};
            vertex.uv = {corner.x / uvMetres, -corner.y / uvMetres};
            mesh.vertices.push_back(vertex);
        }
        mesh.indices = {0, 1, 2, 0, 2, 3};
        return mesh;
    }
    mesh.vertices.reserve(static_cast<std::size_t>(grid.width) * grid.height);
    for (int row = 0; row < grid.height; ++row) {
        for (int col = 0; col < grid.width; ++col) {
            const float value = field.values[static_cast<std::size_t>(row) * grid.width + col];
            Vertex vertex;
            const float x = grid.footprintMin.x + (col + 0.5f) * cell.x;
            const float z = grid.footprintMin.y + (row + 0.5f) * cell.y;
            vertex.position = {x, field.heightMin + (field.heightMax - field.heightMin) * value, z};
            vertex.uv = {x / uvMetres, -z / uvMetres};
            mesh.vertices.push_back(vertex);
        }
    }
    for (int row = 0; row + 1 < grid.height; ++row) {
        for (int col = 0; col + 1 < grid.width; ++col) {
            const auto at = [&](int c, int r) { return static_cast<std::uint32_t>(r * grid.width + c); };
            // Counter-clockwise seen from above (+y): rows run towards +z.
            mesh.indices.insert(mesh.indices.end(), {at(col, row), at(col, row + 1), at(col + 1, row + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(col, row), at(col + 1, row + 1), at(col + 1, row)});
        }
    }
    computeSmoothNormals(mesh);
    return mesh;
}

} // namespace stoa
