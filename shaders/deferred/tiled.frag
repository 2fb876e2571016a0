#version 330 core
#include "common/frame.glsl"
#include "08_deferred/student/g_buffer.glsl"
#include "deferred/gbuffer_read.glsl"
#include "deferred/lighting.glsl"
#include "deferred/ambient_light.glsl"
// Lab 08's tiled pass, one full-screen pass for all the light: the ambient
// light and the moon, then the point lights, each pixel looping over the
// lights of its tile only, from the lists the student's buildTileLightLists()
// made on the CPU. With uCountOnly it writes the length of its tile's list
// instead (the tile heat map).

uniform samplerBuffer uLights;       // three texels per light (lighting.glsl)
uniform isamplerBuffer uTileOffsets; // tile t's lights: uTileLights[offsets[t] .. offsets[t + 1] - 1]
uniform isamplerBuffer uTileLights;
uniform int uTileSize;
uniform int uTileColumns;   // tiles across the picture
uniform float uCutoff;
uniform float uShininess;
uniform bool uCountOnly;

out vec4 fragColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    ivec2 tile = pixel / uTileSize;
    int t = tile.y * uTileColumns + tile.x;
    int first = texelFetch(uTileOffsets, t).r;
    int end = texelFetch(uTileOffsets, t + 1).r;
    if (uCountOnly) {
        fragColor = vec4(float(end - first));
        return;
    }
    Surface surface = readSurface(pixel);
    vec3 color = ambientLight(surface, pixel, uShininess);
    if (surface.sky) {
        fragColor = vec4(color, 1.0);
        return;
    }
    for (int k = first; k < end; ++k) {
        int light = texelFetch(uTileLights, k).r;
        // The tile's list is conservative: skip a light whose reach (w) ends before this pixel.
        vec4 positionReach = texelFetch(uLights, 3 * light);
        vec3 toLight = positionReach.xyz - surface.position;
        if (dot(toLight, toLight) > positionReach.w * positionReach.w) continue;
        vec3 position, lightColor, attenuation;
        fetchLight(uLights, light, position, lightColor, attenuation);
        color += pointLightShade(surface.position, surface.normal, surface.albedo, surface.specular, uShininess, position,
                                 lightColor, attenuation, uCutoff);
    }
    fragColor = vec4(color, 1.0);
}
