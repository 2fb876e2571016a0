// Material and light types shared by the framework's shaders and the labs.
// They mirror stoa::Material, stoa::DirectionalLight and stoa::PointLight.

struct Material {
    vec3 ambient;     // k_a
    vec3 diffuse;     // k_d
    vec3 specular;    // k_s
    float shininess;  // n, the Blinn-Phong exponent
};

struct DirectionalLight {
    vec3 direction;   // world space, the way the light travels
    vec3 color;       // I_light
};

struct PointLight {
    vec3 position;    // world space
    vec3 color;       // I_light at distance 0
    vec3 attenuation; // (constant, linear, quadratic)
};

#define MAX_DIRECTIONAL_LIGHTS 4
#define MAX_POINT_LIGHTS 8
