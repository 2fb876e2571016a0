#include <stoa/gl/GpuResources.hpp>

namespace stoa {

namespace {

GpuResources* g_current = nullptr;   // the current context's; contexts are one at a time per process

} // namespace

GpuResources::~GpuResources() {
    m_caches.clear();   // while this is still current: their GL objects tell this state cache
    if (g_current == this) g_current = nullptr;
}

GpuResources& GpuResources::current() {
    if (g_current) return *g_current;
    static GpuResources none;
    return none;
}

void GpuResources::makeCurrent(GpuResources* resources) {
    g_current = resources;
    if (resources) resources->m_state.reset();   // a fresh context: GL's defaults
}

} // namespace stoa
