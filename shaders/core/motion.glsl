// Where a camera pixel's surface point was in the previous frame, as a clip position of the previous
// camera: a moving instance moves the point with it. That needs the instance, which only the camera's
// visibility path records (frame.visibilityIds; the classic G-buffer path: camera motion only). A point that
// did not move goes through frame.reprojection (exact for a camera that stood still). The includer
// declares `frame` (FrameUniforms) and defines MOTION_FIRST_BINDING: the visibility IDs, the drawn
// (instance, triangle) list and the instance table are bound there and at the next two
// (declarePreviousFrameInputs in src/core/previous_frame.h).
#ifndef PENUMBRA_MOTION_GLSL
#define PENUMBRA_MOTION_GLSL
layout(set = 0, binding = MOTION_FIRST_BINDING) uniform usampler2D visibilityIds;
layout(set = 0, binding = MOTION_FIRST_BINDING + 1, std430) readonly buffer DrawnTriangles { uvec2 drawnTriangles[]; };
layout(set = 0, binding = MOTION_FIRST_BINDING + 2, std430) readonly buffer Instances { GpuInstance instances[]; };
vec4 previousClip(ivec2 pixel, float depth, vec3 p) {
    const uint id = frame.visibilityIds != 0u ? texelFetch(visibilityIds, pixel, 0).r : 0u;
    if (id != 0u) {
        const mat4 toPrevious = instances[drawnTriangles[id - 1u].x].toPrevious;
        if (toPrevious != mat4(1.0)) return frame.previousViewProj * (toPrevious * vec4(p, 1.0));
    }
    // (ndc, depth, 1) is this frame's clip position divided by its w: scaled back, so that w is the
    // previous view's depth, as the other branch gives it.
    const vec2 ndc = (vec2(pixel) + 0.5) / vec2(frame.width, frame.height) * 2.0 - 1.0;
    return frame.reprojection * vec4(ndc, depth, 1.0) * (frame.viewProj * vec4(p, 1.0)).w;
}
#endif
