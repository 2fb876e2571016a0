#include <stoa/editor/EditorScene.hpp>

#include <algorithm>

namespace stoa {

namespace {
template <typename Items>
auto findById(Items& items, std::uint32_t id) -> decltype(&items.front()) {
    for (auto& item : items)
        if (item.id == id) return &item;
    return nullptr;
}
} // namespace

EditorObject* EditorScene::findObject(std::uint32_t id) { return findById(objects, id); }
const EditorObject* EditorScene::findObject(std::uint32_t id) const { return findById(objects, id); }
EditorLight* EditorScene::findLight(std::uint32_t id) { return findById(lights, id); }
const EditorLight* EditorScene::findLight(std::uint32_t id) const { return findById(lights, id); }

const EditorMaterial* EditorScene::findMaterial(const std::string& name) const {
    for (const EditorMaterial& material : materials)
        if (material.name == name) return &material;
    return nullptr;
}

EditorMaterial* EditorScene::findMaterial(const std::string& name) {
    return const_cast<EditorMaterial*>(static_cast<const EditorScene&>(*this).findMaterial(name));
}

std::uint32_t EditorScene::nextId() const {
    std::uint32_t largest = 0;
    for (const EditorObject& object : objects) largest = std::max(largest, object.id);
    for (const EditorLight& light : lights) largest = std::max(largest, light.id);
    return largest + 1;
}

EditorObject& EditorScene::addObject(std::string name, std::string mesh, std::string material) {
    EditorObject object;
    object.id = nextId();
    object.name = std::move(name);
    object.mesh = std::move(mesh);
    object.material = std::move(material);
    objects.push_back(std::move(object));
    return objects.back();
}

bool EditorScene::removeObject(std::uint32_t id) {
    const auto it = std::find_if(objects.begin(), objects.end(), [&](const EditorObject& o) { return o.id == id; });
    if (it == objects.end()) return false;
    objects.erase(it);
    return true;
}

} // namespace stoa
