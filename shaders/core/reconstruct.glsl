// World position from a depth-buffer value: shared by every pass that reads a depth image.
vec3 unproject(mat4 invViewProj, vec2 uv, float depth) {
    vec4 p = invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0);
    return p.xyz / p.w;
}

// World position of a full-resolution camera pixel.
vec3 pixelWorldPosition(FrameUniforms frame, ivec2 pixel, float depth) {
    return unproject(frame.invViewProj, (vec2(pixel) + 0.5) / vec2(frame.width, frame.height), depth);
}
