#version 460
// Camera translucency, last pass (src/dsm/translucency.h), one thread per pixel: the pixel's kept
// layers, lit by oit_shade.comp, composited front to back over the lit opaque image ("hdr", read and
// written in place):
//   C = sum_i T_i a_i L_i,  T_i = prod_{j<i} (1 - a_j),  out = C + T_n x opaque.
// Fragments beyond OIT_MAX_LIST are merged into one layer behind the kept ones: their combined alpha
// (from the log-transmittance of all the pixel's fragments, which oit_sort.comp summed), the last
// kept fragment's radiance. Only the radiance AOVs (final, direct, indirect) are composited; the
// others keep the opaque surface.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "dsm/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = OIT_BLEND_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = OIT_BLEND_HEADS, std430) readonly buffer Heads { uint heads[]; };
layout(set = 0, binding = OIT_BLEND_LAYERS, std430) readonly buffer Layers { uvec4 header; uvec2 entries[]; } layers;
layout(set = 0, binding = OIT_BLEND_NODES, std430) readonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = OIT_BLEND_HDR, rgba32f) uniform image2D hdr;
layout(push_constant) uniform Push { OitPush pc; };

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    uint aov = frame.aov;
    if (any(greaterThanEqual(pixel, ivec2(pc.width, pc.height))) ||
        (aov != AOV_FINAL && aov != AOV_DIRECT && aov != AOV_INDIRECT))
        return;
    uint base = (uint(pixel.y) * pc.width + uint(pixel.x)) * OIT_HEADER_UINTS;
    uint first = heads[base];
    if (first == DSM_NONE) return;  // no translucent fragment in front of the opaque surface
    uint count = heads[base + 1u], length = heads[base + 3u];
    vec3 sum = vec3(0.0), last = vec3(0.0);
    float t = 1.0, logKept = 0.0;
    for (uint i = 0; i < count; ++i) {
        uvec4 node = nodes[layers.entries[first + i].x];
        vec3 l = uintBitsToFloat(node.xyz);
        float a = unpackHalf2x16(node.w).y;
        sum += t * a * l;
        t *= 1.0 - a;
        logKept += log(max(1.0 - a, 1e-7));
        last = l;
    }
    // Fragments beyond the cap (all behind the last kept one) are not dropped: they are composited
    // as one layer of their combined alpha with the last kept fragment's radiance.
    if (length > count) {
        float tail = min(exp(uintBitsToFloat(heads[base + 2u]) - logKept), 1.0);
        sum += t * (1.0 - tail) * last;
        t *= tail;
    }
    vec4 opaque = imageLoad(hdr, pixel);
    imageStore(hdr, pixel, vec4(sum + t * opaque.rgb, 1.0 - t * (1.0 - opaque.a)));
}
