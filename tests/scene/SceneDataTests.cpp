// Issue 10, items 2-4: the scene as data (transforms with a parent, bounds in
// object and world space, draw lists, materials resolved when built), the
// per-frame uniform block, instancing, and the student's visibility test a
// framework renderer calls.

#include "catch.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/camera/Camera.hpp>
#include <stoa/core/Paths.hpp>
#include <stoa/geometry/Shapes.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/image/Image.hpp>
#include <stoa/core/StudentCode.hpp>
#include <stoa/render/ForwardRenderer.hpp>
#include <stoa/render/FrameUniforms.hpp>
#include <stoa/render/InstancedMesh.hpp>
#include <stoa/scene/MeshObject.hpp>
#include <stoa/scene/Scene.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstddef>
#include <memory>

using namespace stoa;

namespace {

bool near(const glm::vec3& a, const glm::vec3& b, float margin = 1e-4f) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(margin)));
}

// A camera at (0, 0, 6) looking at the origin, as an orbit camera at distance 6
// with yaw and pitch 0 would be: it needs none of lab 01's camera functions.
class FixedCamera final : public Camera {
public:
    glm::vec3 eyePosition() const override { return {0.0f, 0.0f, 6.0f}; }
    glm::vec3 lookTarget() const override { return glm::vec3(0.0f); }
    void mouseDragged(const InputState&, glm::vec2) override {}
};

glm::vec3 originOf(const Object& object) { return glm::vec3(object.modelMatrix()[3]); }

// The pixel (row 0 at the top, as Image keeps it) where `camera` sees `point`
// in a 64x32 frame.
glm::ivec2 pixelOf(const Camera& camera, const glm::vec3& point) {
    const glm::vec4 clip = camera.projectionMatrix(2.0f) * camera.viewMatrix() * glm::vec4(point, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {static_cast<int>((ndc.x * 0.5f + 0.5f) * 64.0f), static_cast<int>((0.5f - ndc.y * 0.5f) * 32.0f)};
}

} // namespace

TEST_CASE("Bounds: a mesh's box and sphere, carried into world space", "[scene]") {
    const Bounds cube = boundsOf(shapes::cube(2.0f));
    CHECK(near(cube.box.min, glm::vec3(-1.0f)));
    CHECK(near(cube.box.max, glm::vec3(1.0f)));
    CHECK(near(cube.sphere.center, glm::vec3(0.0f)));
    CHECK(cube.sphere.radius == Approx(std::sqrt(3.0f)));

    // Turned 45 degrees about Y, scaled by 2 and moved: the box grows to hold
    // the turned cube, the sphere keeps its shape.
    const glm::mat4 transform = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), {10.0f, 0.0f, 0.0f}),
                                                       glm::radians(45.0f), {0.0f, 1.0f, 0.0f}),
                                           glm::vec3(2.0f));
    const Bounds world = transformed(cube, transform);
    const float half = 2.0f * std::sqrt(2.0f);
    CHECK(near(world.box.min, {10.0f - half, -2.0f, -half}));
    CHECK(near(world.box.max, {10.0f + half, 2.0f, half}));
    CHECK(near(world.sphere.center, {10.0f, 0.0f, 0.0f}));
    CHECK(world.sphere.radius == Approx(2.0f * std::sqrt(3.0f)));
    CHECK(world.box.contains({10.0f, 1.9f, 0.0f}));
    CHECK_FALSE(world.box.contains({10.0f, 2.1f, 0.0f}));
    CHECK(near(boundsOf(Mesh{}).box.max, glm::vec3(0.0f)));
}

TEST_CASE("Objects: a child follows its parent, and bounds carry into world space", "[scene]") {
    HeadlessContext context;
    Scene scene;
    auto mesh = std::make_shared<const GpuMesh>(shapes::cube(1.0f));
    auto& cart = scene.add(std::make_unique<MeshObject>(mesh));
    auto& wheel = scene.add(std::make_unique<MeshObject>(mesh));
    wheel.setParent(&cart);
    wheel.position = {1.0f, 0.0f, 0.0f};
    wheel.scale = glm::vec3(0.5f);

    CHECK(near(originOf(wheel), {1.0f, 0.0f, 0.0f}));
    cart.position = {0.0f, 0.0f, -5.0f};
    cart.rotationDegrees = {0.0f, 90.0f, 0.0f};   // +X turns to -Z
    CHECK(near(originOf(wheel), {0.0f, 0.0f, -6.0f}));
    cart.scale = glm::vec3(2.0f);
    CHECK(near(originOf(wheel), {0.0f, 0.0f, -7.0f}));
    CHECK(wheel.modelMatrix() == cart.modelMatrix() * wheel.localMatrix());

    // The mesh's bounds, in object space and carried into world space.
    REQUIRE(wheel.localBounds());
    CHECK(near(wheel.localBounds()->box.max, glm::vec3(0.5f)));
    const Bounds world = *wheel.worldBounds();
    CHECK(near(world.box.min, {-0.5f, -0.5f, -7.5f}));   // the cart's 2 times the wheel's 0.5
    CHECK(near(world.box.max, {0.5f, 0.5f, -6.5f}));
    CHECK(near(world.sphere.center, {0.0f, 0.0f, -7.0f}));
    CHECK(world.sphere.radius == Approx(std::sqrt(3.0f) * 0.5f));

    // A group node: no bounds, draws nothing, moves its children.
    Object group;
    CHECK_FALSE(group.worldBounds());
    cart.setParent(&group);
    group.position = {0.0f, 3.0f, 0.0f};
    CHECK(near(originOf(wheel), {0.0f, 3.0f, -7.0f}));

    // The draw list carries the world matrices, and the resolved material.
    const DrawList list = buildDrawList(scene);
    REQUIRE(list.size() == 2);
    CHECK(list[1].model == wheel.modelMatrix());
    CHECK(list[1].mesh == mesh.get());
    CHECK(list[1].material == &wheel.material);
    CHECK(list[1].diffuseMap == nullptr);
    CHECK(list[1].object == &wheel);
}

TEST_CASE("FrameUniforms: FrameBlock matches the std140 block of common/frame.glsl", "[scene]") {
    HeadlessContext context;
    const Program program = Program::fromFiles("instanced/instanced.vert", "instanced/instanced.frag",
                                               {paths::shadersDir()});
    const GLuint block = glGetUniformBlockIndex(program.id(), FrameUniforms::kBlockName);
    REQUIRE(block != GL_INVALID_INDEX);
    GLint size = 0;
    glGetActiveUniformBlockiv(program.id(), block, GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    CHECK(size == static_cast<GLint>(sizeof(FrameBlock)));
    const std::pair<const char*, std::size_t> members[] = {
        {"uView", offsetof(FrameBlock, view)},
        {"uProjection", offsetof(FrameBlock, projection)},
        {"uCameraPosition", offsetof(FrameBlock, cameraPosition)},
        {"uAmbient", offsetof(FrameBlock, ambient)},
        {"uDirectionalLightCount", offsetof(FrameBlock, directionalLightCount)},
        {"uPointLightCount", offsetof(FrameBlock, pointLightCount)},
        {"uDirectionalLights[0].direction", offsetof(FrameBlock, directionalLights[0].direction)},
        {"uDirectionalLights[1].color", offsetof(FrameBlock, directionalLights[1].color)},
        {"uPointLights[0].position", offsetof(FrameBlock, pointLights[0].position)},
        {"uPointLights[7].attenuation", offsetof(FrameBlock, pointLights[7].attenuation)},
    };
    for (const auto& [name, offset] : members) {
        GLuint index = GL_INVALID_INDEX;
        glGetUniformIndices(program.id(), 1, &name, &index);
        INFO(name);
        REQUIRE(index != GL_INVALID_INDEX);
        GLint glOffset = -1;
        glGetActiveUniformsiv(program.id(), 1, &index, GL_UNIFORM_OFFSET, &glOffset);
        CHECK(glOffset == static_cast<GLint>(offset));
    }
}

TEST_CASE("A framework renderer culls with the student's visibility test when asked to, and draws everything otherwise",
          "[scene]") {
    HeadlessContext context;
    const Program program = Program::fromFiles("instanced/per_object.vert", "instanced/instanced.frag",
                                               {paths::shadersDir()});
    Scene scene;
    scene.ambient = glm::vec3(1.0f);
    auto mesh = std::make_shared<const GpuMesh>(shapes::cube(1.0f));
    Material red, green;
    red.diffuse = {1.0f, 0.0f, 0.0f};
    green.diffuse = {0.0f, 1.0f, 0.0f};
    auto& left = scene.add(std::make_unique<MeshObject>(mesh, red));
    left.position = {-1.0f, 0.0f, 0.0f};
    auto& right = scene.add(std::make_unique<MeshObject>(mesh, green));
    right.position = {1.0f, 0.0f, 0.0f};
    const FixedCamera camera;
    Framebuffer target(64, 32);
    ForwardRenderer renderer;
    renderer.clearColor = glm::vec3(0.0f);

    auto render = [&] {
        target.bind();
        renderer.render(scene, camera, program, {64, 32});
        return target.readColor();
    };
    const glm::ivec2 atLeft = pixelOf(camera, left.position), atRight = pixelOf(camera, right.position);
    Image all = render();
    CHECK(renderer.drawnCount() == 2);
    CHECK(all.pixel(atLeft.x, atLeft.y) == glm::u8vec4(255, 0, 0, 255));    // the red cube on the left
    CHECK(all.pixel(atRight.x, atRight.y) == glm::u8vec4(0, 255, 0, 255));  // the green one on the right

    // The student's visibility test (one would test the sphere against the
    // frustum's planes): here, a double that keeps only what lies left of x = 0.
    StudentCodeScope scope;
    std::vector<BoundingSphere> asked;
    studentCode().culling.isVisible = [&](const BoundingSphere& sphere, const glm::mat4& viewProjection) {
        asked.push_back(sphere);
        CHECK(viewProjection == camera.projectionMatrix(2.0f) * camera.viewMatrix());
        return sphere.center.x < 0.0f;
    };
    renderer.cull = true;
    Image culled = render();
    REQUIRE(asked.size() == 2);
    CHECK(near(asked[0].center, {-1.0f, 0.0f, 0.0f}));
    CHECK(asked[0].radius == Approx(std::sqrt(3.0f) / 2.0f));
    CHECK(renderer.drawnCount() == 1);
    CHECK(renderer.culledCount() == 1);
    CHECK(culled.pixel(atLeft.x, atLeft.y) == glm::u8vec4(255, 0, 0, 255));
    CHECK(culled.pixel(atRight.x, atRight.y) == glm::u8vec4(0, 0, 0, 255));

    // Culling off: everything is drawn, and the test is not asked.
    renderer.cull = false;
    render();
    CHECK(asked.size() == 2);
    CHECK(renderer.drawnCount() == 2);
}

TEST_CASE("InstancedMesh: per-instance transforms and colours in one draw", "[scene]") {
    HeadlessContext context;
    const Program program = Program::fromFiles("instanced/instanced.vert", "instanced/instanced.frag",
                                               {paths::shadersDir()});
    Scene lights;
    lights.ambient = glm::vec3(1.0f);
    const FixedCamera camera;
    FrameUniforms frame;
    frame.update(camera, 2.0f, lights);
    frame.bind();
    program.bindUniformBlock(FrameUniforms::kBlockName, FrameUniforms::kBinding);

    InstancedMesh cubes(shapes::cube(1.0f));
    cubes.setInstances({{glm::translate(glm::mat4(1.0f), {-1.0f, 0.0f, 0.0f}), {0.0f, 0.0f, 1.0f, 1.0f}},
                        {glm::translate(glm::mat4(1.0f), {1.0f, 0.0f, 0.0f}), {1.0f, 1.0f, 0.0f, 1.0f}}});
    CHECK(cubes.instanceCount() == 2);
    Framebuffer target(64, 32);
    PassDescription pass = passInto(target);
    pass.clear.color = pass.clear.depth = true;
    beginPass(pass);
    program.use();
    cubes.draw();
    const Image image = target.readColor();
    const glm::ivec2 atLeft = pixelOf(camera, {-1.0f, 0.0f, 0.0f}), atRight = pixelOf(camera, {1.0f, 0.0f, 0.0f});
    CHECK(image.pixel(atLeft.x, atLeft.y) == glm::u8vec4(0, 0, 255, 255));
    CHECK(image.pixel(atRight.x, atRight.y) == glm::u8vec4(255, 255, 0, 255));
    CHECK(image.pixel(2, 2) == glm::u8vec4(0, 0, 0, 255));
    CHECK(glGetError() == GL_NO_ERROR);
}
