#include "GlTestSupport.hpp"

#include <stoa/app/HeadlessContext.hpp>
#include <stoa/geometry/Mesh.hpp>
#include <stoa/gl/Buffer.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/Framebuffer.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/gl/GpuMesh.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/image/Image.hpp>

using namespace stoa;
using stoa::test::describe;
using stoa::test::glShadersDir;
using stoa::test::near;

namespace {

/// The clip-space square [-1, 1]^2 facing +Z, uv (0,0) at its bottom-left.
Mesh clipSquare(bool indexed) {
    Mesh mesh;
    const Vertex corners[4] = {{{-1, -1, 0}, {0, 0, 1}, {0, 0}},
                               {{1, -1, 0}, {0, 0, 1}, {1, 0}},
                               {{1, 1, 0}, {0, 0, 1}, {1, 1}},
                               {{-1, 1, 0}, {0, 0, 1}, {0, 1}}};
    if (indexed) {
        mesh.vertices.assign(corners, corners + 4);
        mesh.indices = {0, 1, 2, 0, 2, 3};
    } else {
        for (int i : {0, 1, 2, 0, 2, 3}) mesh.vertices.push_back(corners[i]);
    }
    return mesh;
}

/// Draws `mesh` with mesh.vert/frag (colour = uv, normal.z) into 16x16.
Image drawn(const GpuMesh& mesh) {
    const Program program = Program::fromFiles(glShadersDir / "mesh.vert", glShadersDir / "mesh.frag", {});
    Framebuffer target(16, 16);
    beginPass(passInto(target, RenderState::overlay()));
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    program.use();
    mesh.draw();
    return target.readColor();
}

void checkSquare(const Image& image) {
    // Pixel centres: uv = (x + 0.5) / 16 across, (15 - y + 0.5) / 16 up (row 0 is the top).
    const auto expected = [](int x, int y) {
        return glm::u8vec4(static_cast<std::uint8_t>((x + 0.5f) / 16.0f * 255.0f + 0.5f),
                           static_cast<std::uint8_t>((15 - y + 0.5f) / 16.0f * 255.0f + 0.5f), 255, 255);
    };
    for (auto [x, y] : {std::pair{0, 0}, {15, 0}, {0, 15}, {15, 15}, {7, 8}}) {
        INFO("pixel " << x << "," << y << ": " << describe(image.pixel(x, y)) << " expected " << describe(expected(x, y)));
        CHECK(near(image.pixel(x, y), expected(x, y), 2));
    }
}

} // namespace

TEST_CASE("GpuMesh: positions, normals and uvs reach attribute locations 0, 1 and 2") {
    HeadlessContext context;
    const GpuMesh mesh(clipSquare(true));
    CHECK(mesh.indexCount() == 6);
    CHECK(mesh.vertexCount() == 4);
    checkSquare(drawn(mesh));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("GpuMesh: the tangent and its handedness reach attribute location 3") {
    HeadlessContext context;
    Mesh square = clipSquare(true);
    for (Vertex& vertex : square.vertices) vertex.tangent = glm::vec4(0.0f, -1.0f, 0.0f, -1.0f);
    const GpuMesh mesh(square);
    const Program program = Program::fromFiles(glShadersDir / "mesh_tangent.vert", glShadersDir / "mesh.frag", {});
    Framebuffer target(16, 16);
    beginPass(passInto(target, RenderState::overlay()));
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    program.use();
    mesh.draw();
    const Image image = target.readColor();
    INFO("centre pixel " << describe(image.pixel(8, 8)));
    // x 0 -> 0.5, y -1 -> 0, w -1 -> 0.
    CHECK(near(image.pixel(8, 8), glm::u8vec4(128, 0, 0, 255), 2));
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("GpuMesh: a mesh without indices draws as a triangle list") {
    HeadlessContext context;
    const GpuMesh mesh(clipSquare(false));
    CHECK(mesh.indexCount() == 0);
    CHECK(mesh.vertexCount() == 6);
    checkSquare(drawn(mesh));
}

TEST_CASE("GpuMesh: uploading another index buffer leaves the bound mesh's indices alone") {
    HeadlessContext context;
    setCheckedMode(true);
    const GpuMesh mesh(clipSquare(true));
    Framebuffer target(4, 4); // EGL has no default framebuffer to draw into
    target.bind();
    mesh.draw(); // leaves its vertex array bound
    GLint before = 0;
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &before);
    Buffer other(GL_ELEMENT_ARRAY_BUFFER);
    other.upload(std::vector<std::uint32_t>{0, 0, 0});
    CHECK(other.size() == 3 * sizeof(std::uint32_t));
    GLint after = 0;
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &after);
    CHECK(after == before);
    mesh.drawInstanced(3);
    checkSquare(drawn(mesh));
    setCheckedMode(false);
}

TEST_CASE("GpuMesh: moves keep the GL objects") {
    HeadlessContext context;
    GpuMesh mesh(clipSquare(true));
    GpuMesh moved(std::move(mesh));
    CHECK(moved.indexCount() == 6);
    checkSquare(drawn(moved));
}

TEST_CASE("Buffer: update overwrites part of the contents") {
    HeadlessContext context;
    Buffer buffer(GL_ARRAY_BUFFER);
    buffer.upload(std::vector<float>{1.0f, 2.0f, 3.0f, 4.0f}, GL_DYNAMIC_DRAW);
    const float two[2] = {20.0f, 30.0f};
    buffer.update(sizeof(float), two, sizeof two);
    float readBack[4] = {};
    glBindBuffer(GL_COPY_READ_BUFFER, buffer.id());
    glGetBufferSubData(GL_COPY_READ_BUFFER, 0, sizeof readBack, readBack);
    CHECK(readBack[0] == 1.0f);
    CHECK(readBack[1] == 20.0f);
    CHECK(readBack[2] == 30.0f);
    CHECK(readBack[3] == 4.0f);

    const GLuint id = buffer.id();
    Buffer moved = std::move(buffer);
    CHECK(buffer.id() == 0);
    CHECK(moved.id() == id);
    CHECK(moved.size() == 4 * sizeof(float));
    CHECK(moved.target() == GL_ARRAY_BUFFER);
    CHECK(glGetError() == GL_NO_ERROR);
}
