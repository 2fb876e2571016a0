#pragma once
// What belongs to one OpenGL context: what the framework knows of its state
// (StateCache), its textures by file (TextureCache), and the caches of the
// layers above, one per type (the Acropolis's uploaded meshes). The context
// (HeadlessContext, Window) owns it and makes it current with itself, so
// nothing GL lives in a process-wide static and a second context never meets
// the first one's objects or state.
//
//   GpuResources::current().state()          // what StateCache::current() returns
//   GpuResources::current().cache<MyMeshes>() // a layer's own cache, made on first use

#include <stoa/gl/StateCache.hpp>
#include <stoa/gl/TextureCache.hpp>

#include <map>
#include <memory>
#include <typeindex>

namespace stoa {

class GpuResources {
public:
    GpuResources() = default;
    /// Empties the layers' caches (their GL objects go while the context is alive), then stops being current.
    ~GpuResources();
    GpuResources(const GpuResources&) = delete;
    GpuResources& operator=(const GpuResources&) = delete;

    /// The resources of the current context. With none current, an empty set
    /// that belongs to no context: a GL object deleted after its context tells it.
    static GpuResources& current();
    /// Called by the context that owns `resources` when it becomes current
    /// (nullptr when it goes).
    static void makeCurrent(GpuResources* resources);

    StateCache& state() { return m_state; }
    TextureCache& textures() { return m_textures; }

    /// The cache of type `T` (default-constructed the first time it is asked
    /// for), destroyed with the context.
    template <typename T>
    T& cache() {
        std::shared_ptr<void>& slot = m_caches[std::type_index(typeid(T))];
        if (!slot) slot = std::make_shared<T>();
        return *static_cast<T*>(slot.get());
    }

private:
    StateCache m_state;
    TextureCache m_textures;
    std::map<std::type_index, std::shared_ptr<void>> m_caches;
};

} // namespace stoa
