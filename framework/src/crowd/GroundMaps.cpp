#include <stoa/crowd/GroundMaps.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/image/HeightMap.hpp>
#include <stoa/image/Image.hpp>

#include <algorithm>
#include <cstdint>
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

} // namespace

GroundMaps loadGroundMaps(const GroundDescription& ground, const std::filesystem::path& worldFile) {
    GroundMaps maps;
    // A map's own message (its file, what is wrong), after the world's line that named it.
    const auto named = [&](const char* which, const InputError& error) {
        return InputError(worldFile.string(), ground.line, std::string("<ground> ") + which + ": " + error.what());
    };
    Image collision;
    try {
        collision = Image::load(ground.collisionMap, 1);
    } catch (const InputError& error) {
        throw named("collision map", error);
    }
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
    HeightSamples heights;
    try {
        heights = loadHeightSamples(ground.heightMap);
    } catch (const InputError& error) {
        throw named("height map", error);
    }
    requireSize(heights.width, heights.height, ground.heightMap, worldFile, ground.line);
    maps.heights.grid = gridOf(ground, heights.width, heights.height);
    maps.heights.values = std::move(heights.values);
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
