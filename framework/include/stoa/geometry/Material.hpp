#pragma once
// The surface description the forward renderer shades with: Blinn-Phong
// coefficients and optional texture maps, as read from an MTL file.

#include <glm/vec3.hpp>

#include <string>

namespace stoa {

/// A Blinn-Phong material. Colours are linear RGB with components in [0, 1].
/// The defaults are what a surface gets when its MTL file (or the lack of
/// one) leaves a value out: a light grey, slightly glossy plastic.
struct Material {
    std::string name = "default";
    glm::vec3 ambient{0.1f};   // k_a, multiplies the ambient light (MTL: Ka)
    glm::vec3 diffuse{0.8f};   // k_d, multiplies N.L (MTL: Kd)
    glm::vec3 specular{0.2f};  // k_s, multiplies (N.H)^n (MTL: Ks)
    float shininess = 32.0f;   // n, the Blinn-Phong exponent (MTL: Ns)
    std::string diffuseMap;    // absolute path of the diffuse texture (MTL: map_Kd); empty = none
    std::string specularMap;   // absolute path of the specular texture (MTL: map_Ks); empty = none
    std::string normalMap;     // absolute path of a tangent-space normal map (MTL: norm); empty = none
    std::string heightMap;     // absolute path of a height (bump) map (MTL: map_bump or bump); empty = none
    float bumpScale = 1.0f;    // multiplies the height map's values (MTL: the -bm option of map_bump)
};

} // namespace stoa
