#include <stoa/scene/DrawList.hpp>
#include <stoa/scene/Scene.hpp>

namespace stoa {

DrawList buildDrawList(const Scene& scene) {
    DrawList list;
    list.reserve(scene.objects().size());
    for (const auto& object : scene.objects()) object->addDraws(list);
    return list;
}

} // namespace stoa
