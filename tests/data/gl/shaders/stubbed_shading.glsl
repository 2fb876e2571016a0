// A lab stub as students meet it: it compiles and returns a neutral value.
struct Material {
    vec3 diffuse;
};

vec3 shade(vec3 normal) {
    // TODO(lab00): light the surface, docs/labs/00_test.md
    return STOA_NOT_IMPLEMENTED(vec3(0.25, 0.5, 0.75));
}
