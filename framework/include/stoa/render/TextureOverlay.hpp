#pragma once
// Draws a texture into a rectangle of the bound framebuffer, over what is there:
// debug views such as a shadow map in a corner of the window.
//
//   TextureOverlay overlay;                         // needs a current context
//   shadowMap.bindDepthTexture(0);
//   program.set("uTexture", 0);
//   overlay.draw(program, {size.x - 256, 0, 256, 256});
//
// The program's vertex shader makes the rectangle from gl_VertexID alone (no
// vertex buffer): shaders/shadows/depth_view.vert is one.

#include <stoa/gl/RenderState.hpp>
#include <stoa/gl/VertexArray.hpp>

#include <glm/vec4.hpp>

namespace stoa {

class Program;

class TextureOverlay {
public:
    /// Creates the (attribute-less) vertex array. Needs a current context.
    TextureOverlay() = default;

    /// Draws 4 vertices as a triangle strip with `program` into `rectangle`
    /// (x, y from the bottom-left corner, width, height; pixels) of the bound
    /// framebuffer, as a pass of its own (RenderState::overlay(): no depth
    /// test, nothing culled). The pass after it states its own viewport and state.
    void draw(const Program& program, const glm::ivec4& rectangle) const { draw(program, rectangle, RenderState::overlay()); }
    /// The same with `state` instead (a full-screen lighting pass that adds
    /// to the target: BlendMode::Additive).
    void draw(const Program& program, const glm::ivec4& rectangle, const RenderState& state) const;

private:
    VertexArray m_vertexArray;
};

} // namespace stoa
