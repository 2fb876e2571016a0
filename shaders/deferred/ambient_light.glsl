// The light every surface gets besides the point lights: ambient light (times
// lab 09's ambient occlusion, when there is one) and the moon; the sky where
// nothing was drawn. Shared by deferred/ambient.frag (before the light volumes)
// and deferred/tiled.frag (which adds its lights to it in the same pass).
// Include after gbuffer_read.glsl and lighting.glsl. No student code here.

uniform sampler2D uAmbientOcclusion;
uniform bool uHasAmbientOcclusion;
uniform vec3 uMoonDirectionView;
uniform vec3 uSky;

vec3 ambientLight(Surface surface, ivec2 pixel, float shininess) {
    if (surface.sky) return uSky;
    float ao = uHasAmbientOcclusion ? texelFetch(uAmbientOcclusion, pixel, 0).r : 1.0;
    vec3 moon = uDirectionalLightCount > 0 ? uDirectionalLights[0].color : vec3(0.0);
    return ambientAndDirectional(surface.position, surface.normal, surface.albedo, surface.specular, shininess, uAmbient,
                                 uMoonDirectionView, moon, ao);
}
