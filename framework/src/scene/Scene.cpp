#include <stoa/scene/Scene.hpp>

namespace stoa {

void Scene::clear() {
    m_objects.clear();
    directionalLights.clear();
    pointLights.clear();
}

} // namespace stoa
