// buildAcropolisScene() on the headless context: the objects and materials it
// places, the mesh cache across rebuilds, the bounds, and a rendered frame
// that shows the scene (set STOA_PREVIEW_DIR to keep the picture).

#include "catch.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/ShaderSource.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/scene/AcropolisScene.hpp>
#include <stoa/scene/MeshObject.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

using namespace stoa;

namespace {

std::set<std::string> objectNames(const Scene& scene) {
    std::set<std::string> names;
    for (const auto& object : scene.objects()) names.insert(object->name);
    return names;
}

const MeshObject& findObject(const Scene& scene, const std::string& name) {
    for (const auto& object : scene.objects())
        if (object->name == name) return dynamic_cast<const MeshObject&>(*object);
    FAIL("no object named " << name);
    throw std::logic_error("unreachable");
}

// A textured sun-and-sky shader: enough to see the scene, not a lab's lighting.
const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
uniform mat4 uModel, uView, uProjection;
uniform mat3 uNormalMatrix;
out vec3 vNormalWorld;
out vec2 vUv;
void main() {
    vNormalWorld = uNormalMatrix * aNormal;
    vUv = aUv;
    gl_Position = uProjection * uView * uModel * vec4(aPosition, 1.0);
}
)";
const char* kFragment = R"(#version 330 core
#include "common/lights.glsl"
in vec3 vNormalWorld;
in vec2 vUv;
uniform Material uMaterial;
uniform bool uHasDiffuseMap;
uniform sampler2D uDiffuseMap;
uniform vec3 uSunDirection, uSunColor, uAmbient;
out vec4 fragColor;
void main() {
    vec3 albedo = uMaterial.diffuse * (uHasDiffuseMap ? texture(uDiffuseMap, vUv).rgb : vec3(1.0));
    float lambert = max(dot(normalize(vNormalWorld), -normalize(uSunDirection)), 0.0);
    fragColor = vec4(albedo * (uAmbient * 2.0 + uSunColor * lambert), 1.0);
}
)";

} // namespace

TEST_CASE("buildAcropolisScene places every object with its material", "[scene][acropolis]") {
    HeadlessContext context;
    Scene scene;
    buildAcropolisScene(scene);

    std::set<std::string> expected{"floor", "temple", "wall", "pedestal", "statue"};
    for (int i = 1; i <= 6; ++i) expected.insert("column " + std::to_string(i));
    CHECK(objectNames(scene) == expected);
    CHECK(scene.objects().size() == expected.size());
    CHECK(scene.ambient == glm::vec3(0.15f));
    REQUIRE(scene.directionalLights.size() == 1);

    CHECK(findObject(scene, "floor").material.name == "floor");
    CHECK(findObject(scene, "column 3").material.name == "marble");
    CHECK(findObject(scene, "pedestal").material.name == "marble");
    CHECK(findObject(scene, "statue").material.name == "statue");
    const MeshObject& wall = findObject(scene, "wall");
    CHECK(wall.material.name == "wall");
    CHECK(std::filesystem::path(wall.material.diffuseMap).filename() == "wall_diffuse.bmp");
    CHECK(std::filesystem::path(wall.material.heightMap).filename() == "wall_height.pgm");
    CHECK(wall.rotationDegrees == glm::vec3(0.0f, 90.0f, 0.0f));
    // The statue stands on the pedestal's top face.
    const Object& pedestal = findObject(scene, "pedestal");
    CHECK(findObject(scene, "statue").position.y == Approx(pedestal.position.y + 0.5f * pedestal.scale.y));
}

TEST_CASE("buildAcropolisScene includes only the objects the options ask for", "[scene][acropolis]") {
    HeadlessContext context;
    Scene scene;
    AcropolisOptions wallOnly;
    wallOnly.floor = wallOnly.columns = wallOnly.temple = wallOnly.statue = false;
    buildAcropolisScene(scene, wallOnly);
    CHECK(objectNames(scene) == std::set<std::string>{"wall"});

    AcropolisOptions threeColumns;
    threeColumns.floor = threeColumns.wall = threeColumns.temple = threeColumns.statue = false;
    threeColumns.columnCount = 3;
    buildAcropolisScene(scene, threeColumns);
    CHECK(objectNames(scene) == std::set<std::string>{"column 1", "column 2", "column 3"});
    // Centred on x = 0, 2.5 m apart.
    CHECK(findObject(scene, "column 1").position.x == Approx(-2.5f));
    CHECK(findObject(scene, "column 2").position.x == Approx(0.0f).margin(1e-6));
}

TEST_CASE("Rebuilding the Acropolis reuses the uploaded meshes", "[scene][acropolis]") {
    HeadlessContext context;
    Scene scene;
    buildAcropolisScene(scene);
    const std::size_t afterFirst = acropolisUploadCount();
    buildAcropolisScene(scene);
    buildAcropolisScene(scene);
    CHECK(acropolisUploadCount() == afterFirst);

    SECTION("a mesh filter uploads filtered copies, once per distinct mesh") {
        AcropolisOptions filtered;
        int calls = 0;
        filtered.meshFilter = [&calls](const Mesh& mesh) {
            ++calls;
            return mesh;
        };
        buildAcropolisScene(scene, filtered);
        // floor, temple, column (shared by 6 objects), wall, pedestal, statue.
        CHECK(calls == 6);
        CHECK(acropolisUploadCount() == afterFirst + 6);
    }
}

TEST_CASE("acropolisBounds covers the objects the options include", "[scene][acropolis]") {
    const auto [lower, upper] = acropolisBounds();
    CHECK(lower.x == Approx(-15.0f));
    CHECK(upper.x == Approx(15.0f));
    CHECK(lower.z == Approx(-15.0f));
    CHECK(upper.z == Approx(15.0f));
    CHECK(lower.y == Approx(0.0f).margin(1e-5));
    CHECK(upper.y == Approx(7.3f));  // the temple's ridge

    AcropolisOptions statueOnly;
    statueOnly.floor = statueOnly.columns = statueOnly.wall = statueOnly.temple = false;
    const auto [statueLower, statueUpper] = acropolisBounds(statueOnly);
    CHECK(statueLower.y == Approx(0.0f).margin(1e-5));             // the pedestal's foot
    CHECK(statueUpper.y == Approx(1.2f + 1.97f).margin(0.01f));    // pedestal plus statue
    CHECK(statueLower.x > 5.0f);
    CHECK(statueUpper.x < 8.0f);
}

TEST_CASE("The Acropolis renders: stone in front, sky above", "[scene][acropolis]") {
    HeadlessContext context;
    Scene scene;
    buildAcropolisScene(scene);   // the model matrices are the test doubles' (support/StudentDoubles.cpp)
    const Program program = Program::fromSources(ShaderSource::fromText(kVertex, "preview.vert", {}),
                                                 ShaderSource::fromText(kFragment, "preview.frag", {paths::shadersDir()}));
    const int width = 480, height = 270;
    Framebuffer target(width, height);
    PassDescription pass;
    pass.target = &target;
    pass.state.cull = CullMode::None;
    pass.clear.color = pass.clear.depth = true;
    pass.clear.colorValue = {0.55f, 0.7f, 0.9f, 1.0f};
    beginPass(pass);
    program.use();
    program.set("uView", glm::lookAt(glm::vec3(3.0f, 5.0f, 19.0f), glm::vec3(0.0f, 2.5f, -3.0f), glm::vec3(0.0f, 1.0f, 0.0f)));
    program.set("uProjection", glm::perspective(glm::radians(50.0f), float(width) / height, 0.1f, 100.0f));
    program.set("uSunDirection", scene.directionalLights.front().direction);
    program.set("uSunColor", scene.directionalLights.front().color);
    program.set("uAmbient", scene.ambient);
    for (const auto& object : scene.objects()) object->draw(program);
    const Image frame = target.readColor();

    if (const char* folder = std::getenv("STOA_PREVIEW_DIR")) frame.savePng(std::filesystem::path(folder) / "acropolis_preview.png");
    const glm::u8vec4 sky(140, 179, 230, 255);
    auto isSky = [&](int x, int y) {
        const glm::u8vec4 p = frame.pixel(x, y);
        return std::abs(p.r - sky.r) <= 2 && std::abs(p.g - sky.g) <= 2 && std::abs(p.b - sky.b) <= 2;
    };
    CHECK(isSky(2, 2));                       // above the temple's roof
    CHECK_FALSE(isSky(width / 2, height - 3)); // the floor
    CHECK_FALSE(isSky(width / 2, height / 2)); // columns or temple
    int covered = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) covered += isSky(x, y) ? 0 : 1;
    CHECK(covered > width * height / 2);
}
