#include <stoa/gl/CubeMap.hpp>

#include <stoa/core/InputError.hpp>
#include <stoa/gl/Debug.hpp>
#include <stoa/image/Image.hpp>

#include <utility>

namespace stoa {

const std::array<const char*, 6> CubeMap::kFaceNames = {"px", "nx", "py", "ny", "pz", "nz"};

CubeMap CubeMap::fromImages(const std::array<Image, 6>& faces, const std::string& source) {
    const int size = faces[0].width();
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const Image& face = faces[i];
        const std::string name = source + " face " + kFaceNames[i];
        if (face.width() != face.height())
            throw InputError(name, 0, "a cube-map face must be square, got " + std::to_string(face.width()) + "x" +
                                          std::to_string(face.height()));
        if (face.width() != size || size < 1)
            throw InputError(name, 0, "every face must have the size of the first (" + std::to_string(size) +
                                          "), got " + std::to_string(face.width()));
        if (face.channels() < 3)
            throw InputError(name, 0, "a cube-map face must be RGB or RGBA, got " + std::to_string(face.channels()) +
                                          " channel(s)");
    }
    GLint previous = 0;
    STOA_GL_CALL(glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &previous));   // creation only, not in a pass
    CubeMap cube;
    cube.m_size = size;
    STOA_GL_CALL(glGenTextures(1, &cube.m_id));
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_CUBE_MAP, cube.m_id));
    STOA_GL_CALL(glPixelStorei(GL_UNPACK_ALIGNMENT, 1));
    for (int i = 0; i < 6; ++i) {
        const Image& face = faces[static_cast<std::size_t>(i)];
        const bool rgba = face.channels() == 4;
        // Row 0 first, unflipped: a cube-map face's first row is its top (see the header).
        STOA_GL_CALL(glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(i), 0, rgba ? GL_RGBA8 : GL_RGB8,
                                  size, size, 0, rgba ? GL_RGBA : GL_RGB, GL_UNSIGNED_BYTE, face.data()));
    }
    STOA_GL_CALL(glPixelStorei(GL_UNPACK_ALIGNMENT, 4));
    STOA_GL_CALL(glGenerateMipmap(GL_TEXTURE_CUBE_MAP));
    STOA_GL_CALL(glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR));
    STOA_GL_CALL(glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR));
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        STOA_GL_CALL(glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE));
    STOA_GL_CALL(glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS));
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_CUBE_MAP, static_cast<GLuint>(previous)));
    return cube;
}

CubeMap CubeMap::fromFolder(const std::filesystem::path& folder) {
    std::array<Image, 6> faces;
    for (std::size_t i = 0; i < faces.size(); ++i)
        faces[i] = Image::load(folder / (std::string(kFaceNames[i]) + ".png"));
    return fromImages(faces, folder.string());
}

CubeMap::~CubeMap() {
    if (m_id) glDeleteTextures(1, &m_id);
}

CubeMap::CubeMap(CubeMap&& other) noexcept
    : m_id(std::exchange(other.m_id, 0)), m_size(std::exchange(other.m_size, 0)) {}

CubeMap& CubeMap::operator=(CubeMap&& other) noexcept {
    if (this != &other) {
        if (m_id) glDeleteTextures(1, &m_id);
        m_id = std::exchange(other.m_id, 0);
        m_size = std::exchange(other.m_size, 0);
    }
    return *this;
}

void CubeMap::bind(int unit) const {
    STOA_GL_CALL(glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit)));
    STOA_GL_CALL(glBindTexture(GL_TEXTURE_CUBE_MAP, m_id));
}

} // namespace stoa
