#include <stoa/editor/EditorScene.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

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
    if (largest < kMaxId) return largest + 1;
    // The largest id is taken: the smallest free one, rather than wrap to 0
    // (which no file accepts) or pass kMaxId (which none accepts either).
    std::vector<std::uint32_t> ids;
    ids.reserve(objects.size() + lights.size());
    for (const EditorObject& object : objects) ids.push_back(object.id);
    for (const EditorLight& light : lights) ids.push_back(light.id);
    std::sort(ids.begin(), ids.end());
    std::uint32_t free = 1;
    for (const std::uint32_t id : ids) {
        if (id > free) break;
        if (id == free) ++free;
    }
    if (free > kMaxId)
        throw std::length_error("EditorScene::nextId(): every id from 1 to " + std::to_string(kMaxId) + " is taken");
    return free;
}

std::string EditorScene::idProblem() const {
    std::map<std::uint32_t, std::string> owners;
    const auto problem = [&](std::uint32_t id, const std::string& where) -> std::string {
        if (id == 0 || id > kMaxId)
            return where + ".id is " + std::to_string(id) + ", but an id is a whole number from 1 to " +
                   std::to_string(kMaxId);
        const auto [first, inserted] = owners.emplace(id, where);
        return inserted ? std::string() : where + ".id " + std::to_string(id) + " is also the id of " + first->second;
    };
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (std::string found = problem(objects[i].id, "objects[" + std::to_string(i) + "]"); !found.empty())
            return found;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (std::string found = problem(lights[i].id, "lights[" + std::to_string(i) + "]"); !found.empty())
            return found;
    return "";
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
