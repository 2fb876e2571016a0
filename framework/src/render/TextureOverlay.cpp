#include <stoa/core/Assert.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/render/TextureOverlay.hpp>

namespace stoa {

void TextureOverlay::draw(const Program& program, const glm::ivec4& rectangle) const {
    STOA_ASSERT(rectangle.z > 0 && rectangle.w > 0,
                "TextureOverlay::draw(): the rectangle must not be empty (x, y, width, height in pixels)");
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    const GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);

    glViewport(rectangle.x, rectangle.y, rectangle.z, rectangle.w);
    glDisable(GL_DEPTH_TEST);
    program.use();
    // Core profile draws need a bound vertex array even without attributes.
    m_vertexArray.bind();
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);

    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    if (depthTest) glEnable(GL_DEPTH_TEST);
}

} // namespace stoa
