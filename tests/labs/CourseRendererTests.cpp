// The course pipeline (stoa/render/CourseRenderer.hpp) on the GPU, with the
// solutions' code of labs 04-10 handed to the framework as in stoa-editor (the
// labs' hand_over.cpp), on small pictures (96x64) of a floor and a cube:
//   - the views' names, both ways;
//   - the culling statistics and each item's level, with a fake lab 06 (visible
//     when x >= 0, level 1 for everything): one culled, one at level 1; nothing
//     culled with culling off; a radius-0 item never culled;
//   - the sun's shadow: the floor behind the cube (from the sun) darkens, the
//     floor in the open does not, and no pixel gets brighter;
//   - the sky: the plain sky colour without the skybox, something else with it,
//     and the floor the same either way;
//   - a red point light reddens the floor under it;
//   - the debug views (albedo, cascades, levels of detail) differ from the
//     picture, and the floor (radius 0) is not tinted by its level;
//   - the passes' list: in an order checkPassOrder() accepts;
//   - DeferredRenderer's passes one by one: after lightPointLights() the light
//     buffer is bound, in the tiled and the volumes modes; a caller's drawing
//     into it reaches the picture; a G-buffer view does not show it.
// Each test makes its own headless context.

#include "catch.hpp"
#include "GlTestSupport.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/camera/OrbitCamera.hpp>
#include <stoa/core/NotImplemented.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/geometry/Material.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/StateCache.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/render/CourseRenderer.hpp>
#include <stoa/render/DeferredRenderer.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

using stoa::test::describe;
using stoa::test::near;

namespace {

constexpr glm::ivec2 kSize{96, 64};

// The solutions' GLSL of labs 04-09 first, as a solutions build's labs see it.
std::vector<std::filesystem::path> searchPath() {
    return {stoa::paths::sourceDir() / "solutions", stoa::paths::shadersDir()};
}

// Keeps every program it loads, for the renderers that point at them.
class ProgramStore {
public:
    const stoa::Program& load(const std::string& vertex, const std::string& fragment) {
        m_programs.push_back(std::make_unique<stoa::Program>(stoa::Program::fromFiles(vertex, fragment, searchPath())));
        return *m_programs.back();
    }
    auto loader() {
        return [this](const std::string& vertex, const std::string& fragment) -> const stoa::Program& {
            return load(vertex, fragment);
        };
    }

private:
    std::vector<std::unique_ptr<stoa::Program>> m_programs;
};

// The pixel (row 0 at the top, as Image keeps it) that `world` lands on.
glm::ivec2 pixelOf(const stoa::Camera& camera, const glm::vec3& world) {
    const float aspect = static_cast<float>(kSize.x) / static_cast<float>(kSize.y);
    const glm::vec4 clip = camera.projectionMatrix(aspect) * camera.viewMatrix() * glm::vec4(world, 1.0f);
    const glm::vec2 window = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(kSize);
    const glm::ivec2 pixel(static_cast<int>(std::floor(window.x)), kSize.y - 1 - static_cast<int>(std::floor(window.y)));
    REQUIRE(pixel.x >= 0);
    REQUIRE(pixel.x < kSize.x);
    REQUIRE(pixel.y >= 0);
    REQUIRE(pixel.y < kSize.y);
    return pixel;
}

glm::u8vec4 at(const stoa::Image& image, glm::ivec2 pixel) { return image.pixel(pixel.x, pixel.y); }

// How many pixels differ by more than `tolerance` levels in some channel.
int differingPixels(const stoa::Image& a, const stoa::Image& b, int tolerance = 8) {
    int count = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (!near(a.pixel(x, y), b.pixel(x, y), tolerance)) ++count;
    return count;
}

long sumOfChannels(const stoa::Image& image) {
    long sum = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const glm::u8vec4 pixel = image.pixel(x, y);
            sum += pixel.r + pixel.g + pixel.b;
        }
    return sum;
}

glm::u8vec4 eightBit(const glm::vec3& color) {
    const glm::vec3 scaled = glm::round(glm::clamp(color, 0.0f, 1.0f) * 255.0f);
    return {static_cast<std::uint8_t>(scaled.r), static_cast<std::uint8_t>(scaled.g),
            static_cast<std::uint8_t>(scaled.b), 255};
}

// Two points on the floor of CourseScene that the tests look at:
//   kInShadow   the ray from it towards the sun passes through the cube (y = 1
//               at x = -1.0, z = 0.1), 0.4 m inside the shadow's edge
//   kInTheOpen  on the sun's side of the cube, nothing between it and the sun
const glm::vec3 kInShadow{-1.4f, 0.0f, -0.2f};
const glm::vec3 kInTheOpen{2.5f, 0.0f, 2.5f};

// A 20 m floor (radius 0: never culled) and a 2 m cube standing on it at the
// origin, seen from above on the -x, +z side; the sky fills the top rows. The
// context is made first and goes last.
class CourseScene {
public:
    CourseScene()
        : m_floorMesh(stoa::shapes::plane(20.0f)), m_cubeMesh(stoa::shapes::cube(2.0f)),
          m_renderer(stoa::CoursePrograms::load(m_programs.loader())), m_target(kSize.x, kSize.y) {
        camera.setProjection(50.0f, 0.1f, 100.0f);

        stoa::CourseItem floor;
        floor.levels = {&m_floorMesh};
        items.push_back(floor);
        stoa::CourseItem cube;
        cube.levels = {&m_cubeMesh, &m_cubeMesh};
        cube.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        cube.sphere = {{0.0f, 1.0f, 0.0f}, std::sqrt(3.0f)};
        items.push_back(cube);

        lighting.ambient = glm::vec3(0.1f);
        lighting.sunDirection = {-0.4f, -1.0f, -0.3f};
        lighting.sunColor = glm::vec3(1.0f);
        lighting.sceneMin = {-10.0f, -1.0f, -10.0f};
        lighting.sceneMax = {10.0f, 3.0f, 10.0f};

        settings.ambientOcclusion = false;
        settings.sky = false;
        settings.shadowMapSize = 512;
        settings.shadowFar = 30.0f;
    }

    /// The frame into a 96x64 target bound beforehand, read back.
    stoa::Image render() {
        m_target.bind();
        m_renderer.render(items, lighting, camera, kSize, settings, nullptr);
        CHECK(stoa::test::takeGlError() == GL_NO_ERROR);
        return m_target.readColor();
    }

    const stoa::CourseRenderer& renderer() const { return m_renderer; }
    const stoa::GpuMesh& cubeMesh() const { return m_cubeMesh; }

    stoa::OrbitCamera camera{{0.0f, 0.5f, 0.0f}, 9.0f, -45.0f, 30.0f};
    std::vector<stoa::CourseItem> items;
    stoa::CourseLighting lighting;
    stoa::CourseSettings settings;

private:
    stoa::HeadlessContext m_context;
    ProgramStore m_programs;
    stoa::GpuMesh m_floorMesh;
    stoa::GpuMesh m_cubeMesh;
    stoa::CourseRenderer m_renderer;
    stoa::Framebuffer m_target;
};

} // namespace

TEST_CASE("Course views: every name maps to its view and back", "[course]") {
    const std::vector<std::string>& names = stoa::courseViewNames();
    REQUIRE(names.size() == static_cast<std::size_t>(stoa::CourseView::Ids) + 1);   // the last view
    for (std::size_t i = 0; i < names.size(); ++i) {
        const auto view = static_cast<stoa::CourseView>(i);
        CAPTURE(names[i]);
        CHECK(stoa::toString(view) == names[i]);
        stoa::CourseView found = i == 0 ? stoa::CourseView::LevelsOfDetail : stoa::CourseView::Final;   // not the answer
        CHECK(stoa::courseViewFromName(names[i], found));
        CHECK(found == view);
    }
    stoa::CourseView untouched = stoa::CourseView::Cascades;
    CHECK_FALSE(stoa::courseViewFromName("shadows", untouched));
    CHECK_FALSE(stoa::courseViewFromName("", untouched));
    CHECK_FALSE(stoa::courseViewFromName("Final", untouched));   // names are lower case
    CHECK(untouched == stoa::CourseView::Cascades);
}

TEST_CASE("Course culling: the lab code's verdicts become stats() and levels()", "[course]") {
    // A fake lab 06: visible on the +x side only, level 1 for everything.
    stoa::StudentCodeScope scope;
    stoa::studentCode().culling.isVisible = [](const stoa::BoundingSphere& sphere, const glm::mat4&) {
        return sphere.center.x >= 0.0f;
    };
    stoa::studentCode().culling.levelOf = [](const stoa::BoundingSphere&, const stoa::Camera&, int, int) { return 1; };
    CourseScene scene;
    scene.camera = stoa::OrbitCamera({0.0f, 0.5f, 0.0f}, 12.0f, 0.0f, 10.0f);   // both cubes in front of it
    scene.settings.shadowMapSize = 256;
    const auto cubeAt = [&scene](float x, float radius) {
        stoa::CourseItem item;
        item.levels = {&scene.cubeMesh(), &scene.cubeMesh()};
        item.model = glm::translate(glm::mat4(1.0f), glm::vec3(x, 1.0f, 0.0f));
        item.sphere = {{x, 1.0f, 0.0f}, radius};
        return item;
    };
    scene.items = {cubeAt(-5.0f, 1.8f), cubeAt(5.0f, 1.8f)};

    scene.render();
    const stoa::CourseStats& stats = scene.renderer().stats();
    CHECK(stats.objects == 2);
    CHECK(stats.culled == 1);
    CHECK(stats.tooSmall == 0);
    CHECK(stats.perLevel[0] == 0);
    CHECK(stats.perLevel[1] == 1);
    CHECK(scene.renderer().levels() == std::vector<int>{-2, 1});

    scene.settings.culling = false;   // every item, at full detail
    scene.render();
    CHECK(scene.renderer().stats().culled == 0);
    CHECK(scene.renderer().stats().perLevel[0] == 2);
    CHECK(scene.renderer().stats().perLevel[1] == 0);
    CHECK(scene.renderer().levels() == std::vector<int>{0, 0});

    scene.settings.culling = true;
    scene.items = {cubeAt(-5.0f, 0.0f)};   // radius 0: neither culled nor given a level
    scene.render();
    CHECK(scene.renderer().stats().culled == 0);
    CHECK(scene.renderer().stats().perLevel[0] == 1);
    CHECK(scene.renderer().levels() == std::vector<int>{0});
}

TEST_CASE("Course: an unfinished lab switches off its own pass, the rest of the frame is drawn", "[course]") {
    // Lab 06 and lab 05 handed over but still stubs (they throw NotImplemented).
    stoa::StudentCodeScope scope;
    stoa::studentCode().culling.isVisible = [](const stoa::BoundingSphere&, const glm::mat4&) -> bool {
        throw stoa::NotImplemented("isVisible()", "06_culling");
    };
    CourseScene scene;
    scene.camera = stoa::OrbitCamera({0.0f, 0.5f, 0.0f}, 12.0f, 0.0f, 10.0f);
    scene.settings.shadowMapSize = 256;
    stoa::CourseItem item;
    item.levels = {&scene.cubeMesh(), &scene.cubeMesh()};
    item.model = glm::translate(glm::mat4(1.0f), glm::vec3(-5.0f, 1.0f, 0.0f));
    item.sphere = {{-5.0f, 1.0f, 0.0f}, 1.8f};
    scene.items = {item, item};

    scene.render();
    const stoa::CourseStats& stats = scene.renderer().stats();
    REQUIRE(stats.switchedOff.size() == 1);
    CHECK(stats.switchedOff[0] == "culling and LOD: isVisible() (lab 06_culling)");
    CHECK(stats.culled == 0);
    CHECK(stats.perLevel[0] == 2);   // every item drawn, at full detail
    CHECK(scene.renderer().levels() == std::vector<int>{0, 0});

    stoa::studentCode().shadows.cascadeSplits = [](float, float, int, float) -> std::vector<float> {
        throw stoa::NotImplemented("cascadeSplits()", "05_shadows");
    };
    scene.render();
    const std::vector<std::string>& off = scene.renderer().stats().switchedOff;
    CHECK(std::find(off.begin(), off.end(), "cascaded shadows: cascadeSplits() (lab 05_shadows)") != off.end());
    CHECK(stoa::test::takeGlError() == GL_NO_ERROR);
}

TEST_CASE("Course shadows: the floor behind the cube darkens, the open floor does not", "[course]") {
    CourseScene scene;
    scene.settings.shadows = true;
    const stoa::Image shadowed = scene.render();
    scene.settings.shadows = false;
    const stoa::Image unshadowed = scene.render();

    const glm::u8vec4 inShadowWith = at(shadowed, pixelOf(scene.camera, kInShadow));
    const glm::u8vec4 inShadowWithout = at(unshadowed, pixelOf(scene.camera, kInShadow));
    INFO("behind the cube: " << describe(inShadowWith) << " with shadows, " << describe(inShadowWithout) << " without");
    CHECK(int(inShadowWithout.r) - int(inShadowWith.r) > 100);   // the sun's ~0.7 gone, the ambient 0.08 left
    const glm::u8vec4 openWith = at(shadowed, pixelOf(scene.camera, kInTheOpen));
    const glm::u8vec4 openWithout = at(unshadowed, pixelOf(scene.camera, kInTheOpen));
    INFO("in the open: " << describe(openWith) << " with shadows, " << describe(openWithout) << " without");
    CHECK(near(openWith, openWithout, 2));
    CHECK(openWith.r > 150);   // lit by the sun

    CHECK(sumOfChannels(shadowed) < sumOfChannels(unshadowed));
    CHECK(differingPixels(shadowed, unshadowed, 30) >= 40);   // the shadow is an area, not a few pixels
    int brighter = 0;   // shadows only take light away
    for (int y = 0; y < kSize.y; ++y)
        for (int x = 0; x < kSize.x; ++x) {
            const glm::u8vec4 with = shadowed.pixel(x, y), without = unshadowed.pixel(x, y);
            if (with.r > without.r + 2 || with.g > without.g + 2 || with.b > without.b + 2) ++brighter;
        }
    CHECK(brighter == 0);
}

TEST_CASE("Course sky: the skybox where nothing was drawn, else the plain sky colour", "[course]") {
    CourseScene scene;
    scene.lighting.skyColor = {0.55f, 0.68f, 0.82f};
    scene.settings.sky = false;
    const stoa::Image plain = scene.render();
    scene.settings.sky = true;
    const stoa::Image skybox = scene.render();

    // The top row is all sky (the floor ends well before the horizon).
    const glm::u8vec4 skyColor = eightBit(scene.lighting.skyColor);
    int plainSky = 0, skyboxSky = 0;
    for (int x = 0; x < kSize.x; ++x) {
        if (near(plain.pixel(x, 0), skyColor, 2)) ++plainSky;
        if (near(skybox.pixel(x, 0), skyColor, 4)) ++skyboxSky;
    }
    INFO("sky colour " << describe(skyColor) << "; plain " << describe(plain.pixel(kSize.x / 2, 0)) << ", skybox "
                       << describe(skybox.pixel(kSize.x / 2, 0)));
    CHECK(plainSky == kSize.x);
    CHECK(skyboxSky == 0);

    // The skybox only where the G-buffer's depth is still the far plane.
    for (const glm::vec3& floor : {kInShadow, kInTheOpen}) {
        const glm::ivec2 pixel = pixelOf(scene.camera, floor);
        INFO("floor pixel (" << pixel.x << ", " << pixel.y << "): " << describe(at(plain, pixel)) << " vs "
                             << describe(at(skybox, pixel)));
        CHECK(near(at(plain, pixel), at(skybox, pixel), 1));
    }
}

TEST_CASE("Course point lights: a red light reddens the floor under it", "[course]") {
    CourseScene scene;
    scene.lighting.sunColor = glm::vec3(0.3f);   // the floor well below white, so that red can show
    const glm::ivec2 under = pixelOf(scene.camera, kInTheOpen);

    const glm::u8vec4 without = at(scene.render(), under);
    CHECK(scene.renderer().stats().pointLights == 0);

    stoa::PointLight red;
    red.position = kInTheOpen + glm::vec3(0.0f, 0.6f, 0.0f);
    red.color = {1.0f, 0.0f, 0.0f};
    scene.lighting.pointLights = {red};
    const glm::u8vec4 with = at(scene.render(), under);
    CHECK(scene.renderer().stats().pointLights == 1);
    CHECK(scene.renderer().stats().tileListEntries > 0);

    INFO("under the light: " << describe(without) << " without it, " << describe(with) << " with it");
    CHECK(std::abs(int(without.r) - int(without.g)) <= 3);   // grey
    CHECK(int(with.r) > int(with.g) + 60);
    CHECK(near(glm::u8vec4(0, with.g, with.b, 0), glm::u8vec4(0, without.g, without.b, 0), 2));   // red only
}

TEST_CASE("Course views: albedo, cascades and levels of detail differ from the picture", "[course]") {
    CourseScene scene;
    scene.settings.view = stoa::CourseView::Final;
    const stoa::Image lit = scene.render();
    const int quarter = kSize.x * kSize.y / 4;
    for (const stoa::CourseView view :
         {stoa::CourseView::Albedo, stoa::CourseView::Cascades, stoa::CourseView::LevelsOfDetail}) {
        scene.settings.view = view;
        const stoa::Image picture = scene.render();
        const int differing = differingPixels(picture, lit);
        INFO(stoa::toString(view) << ": " << differing << " of " << kSize.x * kSize.y << " pixels differ");
        if (view == stoa::CourseView::LevelsOfDetail) {
            // Only the cube (radius > 0) is tinted: the floor is as in the picture.
            CHECK(differing > 100);
            const glm::ivec2 floor = pixelOf(scene.camera, kInTheOpen);
            CHECK(near(at(picture, floor), at(lit, floor), 1));
            const glm::ivec2 cubeFace = pixelOf(scene.camera, {-1.0f, 1.0f, 0.0f});   // the -x face's centre
            CHECK_FALSE(near(at(picture, cubeFace), at(lit, cubeFace), 8));
        } else {
            CHECK(differing > quarter);
        }
    }
}

TEST_CASE("Course passes: each reads only what an earlier pass wrote, every stage has one", "[course]") {
    stoa::HeadlessContext context;
    ProgramStore programs;
    const stoa::CourseRenderer renderer(stoa::CoursePrograms::load(programs.loader()));
    const std::vector<stoa::PassSignature> passes = renderer.passes();
    CHECK_NOTHROW(stoa::checkPassOrder(passes));   // as the constructor does
    REQUIRE(passes.size() >= static_cast<std::size_t>(stoa::CoursePass::Count));
    CHECK(passes.front().name == "culling and LOD");
    CHECK(passes.front().reads.empty());
    bool drawsOutput = false;
    for (const stoa::PassSignature& pass : passes) {
        CAPTURE(pass.name);
        CHECK_FALSE(pass.writes.empty());
        drawsOutput = drawsOutput || pass.writes.contains(stoa::FrameTarget::Output);
    }
    CHECK(drawsOutput);
}

TEST_CASE("DeferredRenderer's passes one by one: a pass of the caller's between lightPointLights() and present()",
          "[course]") {
    stoa::HeadlessContext context;
    ProgramStore programs;
    stoa::DeferredRenderer renderer(stoa::DeferredPrograms::load(programs.loader()));
    stoa::Framebuffer target(kSize.x, kSize.y);
    const stoa::OrbitCamera camera({0.0f, 0.0f, 0.0f}, 5.0f, 0.0f, 20.0f);
    stoa::PointLight light;
    light.position = {0.0f, 1.0f, 0.0f};
    const glm::u8vec4 green(0, 255, 0, 255);

    for (const stoa::LightingMode mode : {stoa::LightingMode::Tiled, stoa::LightingMode::Volumes}) {
        CAPTURE(stoa::toString(mode));
        stoa::DeferredSettings settings;
        settings.mode = mode;
        renderer.renderGeometry({}, camera, kSize);
        renderer.beginLighting(camera, kSize, stoa::SceneLighting{});
        renderer.lightPointLights({}, {light}, stoa::SceneLighting{}, settings);
        const stoa::Framebuffer& lightBuffer = renderer.lightBuffer();
        CHECK(stoa::StateCache::current().drawFramebuffer() == lightBuffer.id());   // left bound for the caller
        CHECK(lightBuffer.width() == kSize.x);
        CHECK(lightBuffer.height() == kSize.y);
        glClearColor(0.0f, 1.0f, 0.0f, 1.0f);   // the caller's own light: green everywhere
        glClear(GL_COLOR_BUFFER_BIT);
        renderer.present(target.id(), settings);
        CHECK(stoa::StateCache::current().drawFramebuffer() == target.id());   // presented into the caller's target
        const stoa::Image picture = target.readColor();
        CHECK(near(picture.pixel(0, 0), green, 1));
        CHECK(near(picture.pixel(kSize.x / 2, kSize.y / 2), green, 1));
        CHECK(near(picture.pixel(kSize.x - 1, kSize.y - 1), green, 1));

        settings.view = stoa::DeferredView::Albedo;   // a G-buffer view shows the G-buffer, not the light buffer
        renderer.present(target.id(), settings);
        CHECK_FALSE(near(target.readColor().pixel(kSize.x / 2, kSize.y / 2), green, 1));
    }
    CHECK(stoa::test::takeGlError() == GL_NO_ERROR);
}
