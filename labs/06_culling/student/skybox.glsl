// Lab 06, part 4: the sky. Read docs/labs/06_culling.md, "The skybox".
// shaders/culling/skybox.vert draws a cube of side 2 around the origin, after
// everything else, with the depth test `less or equal` and no depth writes:
//   gl_Position = skyboxClipPosition(aPosition, uView, uProjection);
//   vDirection = aPosition;
// and shaders/culling/skybox.frag colours each fragment with
//   fragColor = vec4(skyColor(uSky, vDirection), 1.0);

// The clip position of the sky cube's corner `corner` (object space, the cube
// centred on the origin) so that the sky stays around the eye however the
// camera moves (only the view's rotation applies) and lies at the far plane
// (its depth after the perspective divide is exactly 1).
vec4 skyboxClipPosition(vec3 corner, mat4 view, mat4 projection) {
    // TODO(lab06): drop the view's translation (mat4(mat3(view))), project,
    // and make z equal to w (docs: "The skybox").
    return STOA_NOT_IMPLEMENTED(vec4(corner, 1.0));
}

// The sky's colour in `direction` (from the eye; need not be unit length).
vec3 skyColor(samplerCube sky, vec3 direction) {
    // TODO(lab06): a cube map is looked up by direction (docs: "The skybox").
    return STOA_NOT_IMPLEMENTED(vec3(0.0));
}
