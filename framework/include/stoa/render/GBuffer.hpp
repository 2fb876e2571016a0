#pragma once
// The geometry buffer of deferred shading (labs 08-09): what the geometry pass
// writes for every pixel, read back by the lighting passes.
//
//   attachment 0  albedo and specular strength   GL_RGBA8   (rgb albedo, a specular)
//   attachment 1  the packed normal              GL_RG16    (two unsigned 16-bit values in [0, 1])
//   depth         depth and stencil              GL_DEPTH24_STENCIL8, a texture
//
// Positions are not stored: a lighting pass rebuilds a pixel's view-space
// position from its depth and the inverse projection. The deferred engine this
// follows (Poulsen et al. 2013) stores its normals as two 16-bit floats; the
// unsigned normalised format here asks the packing to map them into [0, 1].
//
//   GBuffer gBuffer(640, 480);
//   PassDescription pass = passInto(gBuffer.target());   ... draw the geometry ...
//   gBuffer.bindTextures(0);                              // units 0, 1, 2: albedo, normal, depth

#include <stoa/gl/Framebuffer.hpp>

#include <glm/vec2.hpp>

#include <cstddef>

namespace stoa {

class GBuffer {
public:
    static constexpr int kAlbedoSpecular = 0;   // colour attachment indices
    static constexpr int kNormal = 1;

    /// No targets; no GL call.
    GBuffer() = default;
    /// The three textures at `width` x `height` pixels. Needs a current context.
    GBuffer(int width, int height);

    /// Makes the targets again when the size differs; true when it did.
    bool resize(glm::ivec2 size);

    /// Binds albedo/specular to `firstUnit`, the packed normal to firstUnit + 1
    /// and depth to firstUnit + 2, for a lighting pass to sample.
    void bindTextures(int firstUnit) const;

    Framebuffer& target() { return m_target; }
    const Framebuffer& target() const { return m_target; }
    glm::ivec2 size() const { return {m_target.width(), m_target.height()}; }

    /// Bytes the three textures hold: 4 + 4 + 4 per pixel.
    std::size_t bytes() const;

private:
    Framebuffer m_target;
};

} // namespace stoa
