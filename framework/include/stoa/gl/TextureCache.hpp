#pragma once
// Texture files loaded once and shared: every MeshObject whose material names
// "column_diffuse.png" draws with the same Texture2D.
//
//   std::shared_ptr<const Texture2D> marble = TextureCache::shared().load(path);
//   marble->bind(0);
//
// The cache does not own the textures (it keeps weak pointers): a texture
// lives as long as someone holds it, then its GL object goes, so the cache
// never keeps GL objects past the context that made them. Like every GL
// object in the framework, a texture belongs to the context that was current
// when it was loaded; the framework uses one context at a time.

#include <stoa/gl/Texture2D.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace stoa {

class TextureCache {
public:
    /// The texture of the file at `path` (with the default TextureOptions:
    /// trilinear mipmaps, repeat), loaded with Texture2D::fromFile() unless a
    /// living texture of the same file is already there. Paths are compared
    /// after std::filesystem::absolute() and lexically_normal(). Throws
    /// InputError naming the file when it is missing or does not decode.
    [[nodiscard]] std::shared_ptr<const Texture2D> load(const std::filesystem::path& path);

    /// How many files have been decoded and uploaded so far (for tests).
    int loadCount() const { return m_loadCount; }
    /// How many cached textures are still alive.
    int aliveCount() const;

    /// The current context's cache (GpuResources), which MeshObject uses.
    static TextureCache& shared();

private:
    std::map<std::string, std::weak_ptr<const Texture2D>> m_textures;  // by normalized absolute path
    int m_loadCount = 0;
};

} // namespace stoa
