#include <stoa/crowd/CrowdWorld.hpp>

// A world holds a handful of types and behaviours: a linear search by name is
// as fast as a map and keeps the data plain vectors.

namespace stoa {

int CrowdWorld::findType(const std::string& name) const {
    for (std::size_t i = 0; i < types.size(); ++i) {
        if (types[i].name == name) return static_cast<int>(i);
    }
    return -1;
}

int CrowdWorld::findBehaviour(const std::string& name) const {
    for (std::size_t i = 0; i < behaviours.size(); ++i) {
        if (behaviours[i].name == name) return static_cast<int>(i);
    }
    return -1;
}

} // namespace stoa
