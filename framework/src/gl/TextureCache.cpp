#include <stoa/gl/GpuResources.hpp>
#include <stoa/gl/TextureCache.hpp>

namespace stoa {

std::shared_ptr<const Texture2D> TextureCache::load(const std::filesystem::path& path) {
    const std::string key = std::filesystem::absolute(path).lexically_normal().string();
    std::weak_ptr<const Texture2D>& slot = m_textures[key];
    if (std::shared_ptr<const Texture2D> alive = slot.lock()) return alive;
    // fromFile throws before the slot is filled, so a bad file is tried again next time.
    auto texture = std::make_shared<const Texture2D>(Texture2D::fromFile(key));
    ++m_loadCount;
    slot = texture;
    return texture;
}

int TextureCache::aliveCount() const {
    int alive = 0;
    for (const auto& entry : m_textures) alive += entry.second.expired() ? 0 : 1;
    return alive;
}

TextureCache& TextureCache::shared() { return GpuResources::current().textures(); }

} // namespace stoa
