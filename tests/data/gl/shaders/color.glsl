// The colour of solid.frag, from a uniform.
uniform vec4 uColor;

vec4 solidColor() {
    return uColor;
}
