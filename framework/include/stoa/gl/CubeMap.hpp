#pragma once
// A cube-map texture: six square faces that a shader samples by direction,
// `texture(uSky, direction)`. The sky of lab 06 is one.
//
//   CubeMap sky = CubeMap::fromFolder(paths::assetsDir() / "sky");   // px.png, nx.png, ...
//   sky.bind(0);
//   program.set("uSky", 0);             // a samplerCube
//
// The faces come in OpenGL's order, +X, -X, +Y, -Y, +Z, -Z, each as an Image
// with row 0 at the top, uploaded as it is: a face's first row is its t = 0.
// Seen from the centre of the cube looking along +X, the +X face's right is -Z
// and its top is +Y (cube maps are left-handed inside; the OpenGL 3.3 spec,
// table 3.21, maps every face). Edges are filtered across faces
// (GL_TEXTURE_CUBE_MAP_SEAMLESS).

#include <stoa/gl/OpenGL.hpp>

#include <array>
#include <filesystem>
#include <string>

namespace stoa {

class Image;

class CubeMap {
public:
    /// The file names fromFolder() reads, in face order: px, nx, py, ny, pz, nz (.png).
    static const std::array<const char*, 6> kFaceNames;

    /// No texture; no GL call.
    CubeMap() = default;
    /// Uploads six square faces of one size (RGB or RGBA), with mipmaps, linear
    /// filtering, clamped. InputError naming the face when one is not square or
    /// differs in size from the first. Leaves the cube-map binding as it was.
    static CubeMap fromImages(const std::array<Image, 6>& faces, const std::string& source = "cube map");
    /// The six kFaceNames PNGs of `folder`; InputError naming a missing or bad file.
    static CubeMap fromFolder(const std::filesystem::path& folder);

    ~CubeMap();
    CubeMap(const CubeMap&) = delete;
    CubeMap& operator=(const CubeMap&) = delete;
    CubeMap(CubeMap&& other) noexcept;
    CubeMap& operator=(CubeMap&& other) noexcept;

    /// Binds to texture unit `unit`; leaves that unit active.
    void bind(int unit) const;

    int size() const { return m_size; }   // texels along a face's edge
    GLuint id() const { return m_id; }    // 0 when empty

private:
    GLuint m_id = 0;
    int m_size = 0;
};

} // namespace stoa
