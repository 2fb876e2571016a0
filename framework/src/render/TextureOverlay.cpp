#include <stoa/core/Assert.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/gl/OpenGL.hpp>
#include <stoa/gl/Program.hpp>
#include <stoa/gl/RenderPass.hpp>
#include <stoa/render/TextureOverlay.hpp>

namespace stoa {

void TextureOverlay::draw(const Program& program, const glm::ivec4& rectangle, const RenderState& state) const {
    STOA_ASSERT(rectangle.z > 0 && rectangle.w > 0,
                "TextureOverlay::draw(): the rectangle must not be empty (x, y, width, height in pixels)");
    // A pass of its own over the rectangle, into what is bound: no depth test,
    // nothing cleared. The next pass states its own viewport and state.
    PassDescription pass;
    pass.viewport = rectangle;
    pass.state = state;
    beginPass(pass);
    program.use();
    // Core profile draws need a bound vertex array even without attributes.
    m_vertexArray.bind();
    STOA_GL_CALL(glDrawArrays(GL_TRIANGLE_STRIP, 0, 4));
}

} // namespace stoa
