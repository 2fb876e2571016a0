#pragma once
// What is drawn: objects and the lights that shine on them.

#include <stoa/scene/Light.hpp>
#include <stoa/scene/Object.hpp>

#include <memory>
#include <vector>

namespace stoa {

class Scene {
public:
    /// Takes ownership; returns the object for further set-up.
    template <typename T>
    T& add(std::unique_ptr<T> object) {
        T& reference = *object;
        m_objects.push_back(std::move(object));
        return reference;
    }
    const std::vector<std::unique_ptr<Object>>& objects() const { return m_objects; }
    void clear();

    glm::vec3 ambient{0.1f};                       // ambient light colour, I_amb = ambient * k_a
    std::vector<DirectionalLight> directionalLights;
    std::vector<PointLight> pointLights;

    /// Upper bounds the framework's shaders are compiled for.
    static constexpr int kMaxDirectionalLights = 4;
    static constexpr int kMaxPointLights = 8;

private:
    std::vector<std::unique_ptr<Object>> m_objects;
};

} // namespace stoa
