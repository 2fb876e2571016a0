// The lighting of labs 08-09, the same in all three renderers (naive forward,
// light volumes, tiles), so that their pictures agree. Everything is in view
// space: the camera at the origin looking down -z. No student code here.

// One point light's Blinn-Phong contribution at P (normal N). The attenuation
// 1 / (c + l d + q d^2) is lowered by the cut-off and rescaled, so that it
// reaches 0 exactly where the brightest channel falls to `cutoff` (the reach of
// lightReach()) and stays 0 beyond: a light volume of that radius misses nothing.
vec3 pointLightShade(vec3 P, vec3 N, vec3 albedo, float specular, float shininess, vec3 lightPosition, vec3 color,
                     vec3 attenuation, float cutoff) {
    vec3 toLight = lightPosition - P;
    float d = length(toLight);
    vec3 L = toLight / max(d, 1e-4);
    float falloff = 1.0 / (attenuation.x + attenuation.y * d + attenuation.z * d * d);
    float peak = max(color.r, max(color.g, color.b));
    float lowest = cutoff / max(peak, 1e-6);
    float windowed = max(falloff - lowest, 0.0) / max(1.0 - lowest, 1e-6);
    vec3 V = normalize(-P);
    vec3 H = normalize(L + V);
    float diffuse = max(dot(N, L), 0.0);
    float highlight = diffuse > 0.0 ? pow(max(dot(N, H), 0.0), shininess) : 0.0;
    return windowed * color * (albedo * diffuse + specular * highlight);
}

// Ambient light (times the ambient occlusion `ao`, 1 without it) and the
// directional light (the moon), for a point of view-space normal N.
vec3 ambientAndDirectional(vec3 P, vec3 N, vec3 albedo, float specular, float shininess, vec3 ambient, vec3 lightDirectionView,
                           vec3 lightColor, float ao) {
    vec3 L = -normalize(lightDirectionView);
    vec3 V = normalize(-P);
    vec3 H = normalize(L + V);
    float diffuse = max(dot(N, L), 0.0);
    float highlight = diffuse > 0.0 ? pow(max(dot(N, H), 0.0), shininess) : 0.0;
    return ambient * albedo * ao + lightColor * (albedo * diffuse + specular * highlight);
}

// The lights as BufferTexture texels, three per light:
// (position in view space, reach), (colour, 0), (attenuation, 0).
void fetchLight(samplerBuffer lights, int i, out vec3 position, out vec3 color, out vec3 attenuation) {
    position = texelFetch(lights, 3 * i).xyz;
    color = texelFetch(lights, 3 * i + 1).rgb;
    attenuation = texelFetch(lights, 3 * i + 2).xyz;
}
