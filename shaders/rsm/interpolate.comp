#version 460
// The paper's speed-up: each full-resolution pixel takes the irradiance of the nearby low-resolution
// gathers that saw a surface like its own (normals within a cone, positions within a few pixel
// footprints), filtered; with fewer than three of its four nearest on its surface (two, where a
// low-resolution cell is smaller than the RSM's texel there), the pixel is appended to a list that
// rsm/gather.comp (RSM_GATHER_LIST) evaluates in full.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "rsm/bindings.h"
#include "core/reconstruct.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = RSM_INTERPOLATE_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = RSM_INTERPOLATE_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = RSM_INTERPOLATE_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = RSM_INTERPOLATE_LOW_IRRADIANCE) uniform sampler2D lowIrradiance;
layout(set = 0, binding = RSM_INTERPOLATE_IRRADIANCE, rgba32f) uniform writeonly image2D outIrradiance;
layout(set = 0, binding = RSM_INTERPOLATE_PIXEL_LIST, std430) buffer PixelList { uvec4 header; uvec2 pixels[]; } list;
layout(set = 0, binding = RSM_INTERPOLATE_LAYERS, std430) readonly buffer Layers { GpuRsmLayer rsmLayers[]; };
layout(push_constant) uniform Push { RsmPush pc; };

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.width, frame.height)))) return;
    float depth = texelFetch(gDepth, pixel, 0).r;
    if (depth >= 1.0) {
        imageStore(outIrradiance, pixel, vec4(0.0));
        return;
    }
    vec3 x = pixelWorldPosition(frame, pixel, depth);
    vec3 n = normalize(texelFetch(gNormal, pixel, 0).xyz);
    // Tolerance: the world footprint of a low-resolution cell at this depth (pixel footprint is
    // 2 d tan(fovy/2) / height) times the distance threshold.
    float footprint = length(x - frame.eye) * frame.pixelSpread;
    float tolerance = pc.distanceThreshold * footprint * float(pc.lowResFactor);

    // Joint bilateral filter over the 4 x 4 nearest low-resolution gathers: a Gaussian of one cell in
    // screen space times a hard same-surface test (rotated patterns make neighbouring gathers
    // independent, so the filter averages their noise). With fewer than `needed` of the four nearest
    // on the pixel's surface, the pixel is gathered in full instead.
    int f = int(pc.lowResFactor);
    ivec2 lowSize = ivec2(pc.width, pc.height);
    vec2 c = (vec2(pixel) + 0.5) / float(f) - 0.5;
    ivec2 base = ivec2(floor(c));
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    int valid = 0;
    // Two of the four nearest suffice where a cell is smaller than the RSM's texel (the VPL spacing)
    // at x (its first layer's: the sun's widest cascade, a spot's map, a cube's first face): the gather cannot resolve the light's change across less than that, so taking it from
    // cells on one side of the pixel adds nothing the RSM itself does not miss. At 1080p that keeps
    // 8-9 in 10 of VC's and Sponza's full gathers; at the suite's 64x48 pins no cell is that small.
    GpuRsmLayer first = rsmLayers[0];
    float rsmTexel = first.texelSize;
    if (first.perspective != 0u) rsmTexel *= max(abs((first.viewProj * vec4(x, 1.0)).w), 1e-3);
    const int needed = footprint * float(pc.lowResFactor) < rsmTexel ? 2 : 3;
    for (int k = 0; k < 16; ++k) {
        ivec2 o = ivec2(k & 3, k >> 2) - 1;
        ivec2 cell = base + o;
        if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, lowSize))) continue;
        ivec2 rep = min(cell * f + f / 2, ivec2(frame.width, frame.height) - 1);
        float d = texelFetch(gDepth, rep, 0).r;
        if (d >= 1.0) continue;
        vec3 xi = pixelWorldPosition(frame, rep, d);
        vec3 ni = normalize(texelFetch(gNormal, rep, 0).xyz);
        // Same surface: similar normal, on x's tangent plane (within one cell footprint), not far
        // along it (grazing views stretch a cell's footprint along the surface, hence the slack).
        if (dot(ni, n) < pc.normalThreshold || abs(dot(n, xi - x)) > tolerance || length(xi - x) > 12.0 * tolerance)
            continue;
        vec2 r = vec2(cell) - c;
        float b = exp(-0.5 * dot(r, r));
        sum += b * texelFetch(lowIrradiance, cell, 0).rgb;
        weight += b;
        if (all(greaterThanEqual(o, ivec2(0))) && all(lessThanEqual(o, ivec2(1)))) ++valid;
    }
    if (valid >= needed && weight > 1e-4) {
        imageStore(outIrradiance, pixel, vec4(sum / weight, 1.0));
    } else {
        uint slot = atomicAdd(list.header.x, 1u);
        list.pixels[slot] = uvec2(pixel);
    }
}
