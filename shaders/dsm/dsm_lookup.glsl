// Deep-shadow-map lookup for the deferred lighting pass (lighting/lighting.comp includes it after its
// own bindings): the transmittance of semi-transparent casters (hair, blended meshes) between a
// light and a receiver, filtered (PCF) over the neighbouring texels through the resolve's links.
// Opaque casters are not in the DSM: lighting multiplies this with the ordinary shadow map.
// Reads `frame` (FrameUniforms) of the including shader.
#include "dsm/dsm_common.glsl"
#include "shadow/cube_face.glsl"

#include "dsm/bindings.h"
layout(set = 0, binding = DSM_LOOKUP_LIGHTS, std430) readonly buffer DsmLights { GpuDsmLight dsmLights[]; };
layout(set = 0, binding = DSM_LOOKUP_HEADS, std430) readonly buffer DsmHeads { uint dsmHeads[]; };
layout(set = 0, binding = DSM_LOOKUP_NODES, std430) readonly buffer DsmNodes { uvec4 dsmNodes[]; };
// The side buffer: per node its upper link (--dsm-lookup links) or, packed, its depth (search).
layout(set = 0, binding = DSM_LOOKUP_SIDE, std430) readonly buffer DsmSide { uint dsmSide[]; };

float dsmNodeDepth(uint n) { return uintBitsToFloat(dsmNodes[n].x); }
float dsmTransmittanceOf(uint n) { return n == DSM_NONE ? 1.0 : uintBitsToFloat(dsmNodes[n].y); }

// The last node of a texel's sorted list with depth <= d (DSM_NONE: nothing in front of d). `hint`
// is a node of that list known to lie at or in front of d (a neighbour link), or DSM_NONE.
uint dsmFind(uint texel, float d, uint hint) {
    uint n = hint;
    if (n == DSM_NONE) {
        n = dsmHeads[texel * DSM_HEAD_UINTS];
        if (n == DSM_NONE || dsmNodeDepth(n) > d) return DSM_NONE;
    }
    for (uint i = 0; i < DSM_MAX_LIST_CAP; ++i) {  // resolved lists are never longer
        uint next = dsmNodes[n].z;
        if (next == DSM_NONE || dsmNodeDepth(next) > d) break;
        n = next;
    }
    return n;
}

// Integral of the unit tent (the bilinear footprint of a texel centred at 0) from -inf to t.
float dsmTentCdf(float t) {
    t = clamp(t, -1.0, 1.0);
    return t < 0.0 ? 0.5 * (t + 1.0) * (t + 1.0) : 1.0 - 0.5 * (1.0 - t) * (1.0 - t);
}

// Weight of texel i (centre i + 0.5) for a box of `width` texels centred at s, each texel spread
// bilinearly: smooth in s for any width, width 0 is plain bilinear. The weights sum to 1.
float dsmTapWeight(float s, float width, int i) {
    float c = float(i) + 0.5;
    if (width < 1e-3) return max(0.0, 1.0 - abs(s - c));
    return (dsmTentCdf(s + 0.5 * width - c) - dsmTentCdf(s - 0.5 * width - c)) / width;
}

// Binary search (--dsm-lookup search): each tap finds its place in its texel's packed list on its
// own, all taps of the kernel in lockstep, so that their reads are in flight together (a walk through
// the neighbour links chains every tap's reads behind the previous tap's). At most
// DSM_SEARCH_TAPS taps (a 3x3 kernel: the default width of 1 texel, and bilinear); wider kernels
// search tap after tap: 16 taps (4x4) in lockstep hold so many registers that the pass's
// occupancy falls and it runs slower than with 9.
#define DSM_SEARCH_TAPS 9

// Transmittance in front of depth d in the list of `texel` (1 for an empty list): the same search
// as the lockstep below, one tap at a time, for kernels wider than a batch. Not the lockstep in a loop
// of batches: that loop's registers slow the default kernel's pass too, so the wide path stays scalar.
float dsmSearchOne(uint texel, float d) {
    uint first = dsmHeads[texel * DSM_HEAD_UINTS];
    if (first == DSM_NONE) return 1.0;
    uint length = dsmHeads[texel * DSM_HEAD_UINTS + 1u];
    uint before = 0u;  // nodes with depth <= d
    while (length > 0u) {
        uint half_ = length / 2u;
        bool ahead = uintBitsToFloat(dsmSide[first + before + half_]) <= d;
        before = ahead ? before + half_ + 1u : before;
        length = ahead ? length - half_ - 1u : half_;
    }
    return before == 0u ? 1.0 : uintBitsToFloat(dsmNodes[first + before - 1u].y);
}

// The weighted sum of the taps' transmittance over [lo, hi] (taps outside the map cast nothing).
float dsmSearchKernel(uint base, int res, ivec2 lo, ivec2 hi, vec2 s, float width, float d) {
    const int nx = hi.x - lo.x + 1, taps = nx * (hi.y - lo.y + 1);
    float sum = 0.0;
    if (taps > DSM_SEARCH_TAPS) {
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) {
                bool inside = x >= 0 && y >= 0 && x < res && y < res;
                float t = inside ? dsmSearchOne(base + uint(y * res + x), d) : 1.0;
                sum += dsmTapWeight(s.y, width, y) * dsmTapWeight(s.x, width, x) * t;
            }
        return sum;
    }
    // Per tap two registers (the shade pass's occupancy depends on them; a third array costs it
    // occupancy): `at`, the first node not yet known to lie in front of d, and
    // `state`, the nodes left to search (times 2) plus 1 once a node in front of d was found.
    uint at[DSM_SEARCH_TAPS], state[DSM_SEARCH_TAPS];
    [[unroll]] for (int k = 0; k < DSM_SEARCH_TAPS; ++k) {
        const ivec2 t = lo + ivec2(k % nx, k / nx);
        const bool inside = k < taps && all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, ivec2(res)));
        const uint texel = base + uint(t.y * res + t.x);
        at[k] = inside ? dsmHeads[texel * DSM_HEAD_UINTS] : DSM_NONE;
        state[k] = at[k] != DSM_NONE ? dsmHeads[texel * DSM_HEAD_UINTS + 1u] << 1 : 0u;
    }
    for (bool searching = true; searching;) {
        searching = false;
        [[unroll]] for (int k = 0; k < DSM_SEARCH_TAPS; ++k) {
            const uint left = state[k] >> 1;
            if (left == 0u) continue;
            const uint half_ = left / 2u;
            const bool ahead = uintBitsToFloat(dsmSide[at[k] + half_]) <= d;
            at[k] = ahead ? at[k] + half_ + 1u : at[k];
            state[k] = ((ahead ? left - half_ - 1u : half_) << 1) | (ahead ? 1u : state[k] & 1u);
            searching = searching || state[k] > 1u;
        }
    }
    [[unroll]] for (int k = 0; k < DSM_SEARCH_TAPS; ++k) {
        if (k >= taps) break;
        const ivec2 t = lo + ivec2(k % nx, k / nx);
        const float tk = (state[k] & 1u) == 0u ? 1.0 : uintBitsToFloat(dsmNodes[at[k] - 1u].y);
        sum += dsmTapWeight(s.y, width, t.y) * dsmTapWeight(s.x, width, t.x) * tk;
    }
    return sum;
}

// Deep opacity map (--shadow dom): transmittance at depth d in `texel`: exp of minus the optical
// depth of the layers in front of d, the layer d lies in counted in proportion (the linear
// interpolation between layer boundaries of Yuksel & Keyser 2008).
float domTransmittance(uint texel, float d, float thickness) {
    uint first = dsmHeads[texel];
    if (first == DSM_NONE) return 1.0;  // the clear value: no strand over this texel
    float x = (d - fromOrderedDepth(first)) / thickness;
    vec4 layers = uintBitsToFloat(dsmNodes[texel]);
    float sigma = 0.0;
    for (int k = 0; k < DOM_LAYERS; ++k) sigma += layers[k] * clamp(x - float(k), 0.0, 1.0);
    return exp(-sigma);
}

// Filtered transmittance at p for light `lightIndex` (1 where it has no DSM). The receiver moves
// `normalOffset` texels along its normal n (hair, whose n is a tangent: towards the light) and its depth
// `depthBias` texels towards the light, so that it does not shadow itself through its own nodes.
float deepShadowTransmittance(uint lightIndex, vec3 p, vec3 n, bool hair) {
    GpuDsmLight dsm = dsmLights[lightIndex];
    if (dsm.layer < 0) return 1.0;
    // A point light: the cube face in p's direction (faces overlap by a margin, so the filter's taps
    // stay inside it).
    if (dsm.projection == DSM_PROJECTION_CUBE) dsm = dsmLights[dsm.firstFace + cubeFace(p - dsm.viewer)];
    float texel = dsm.texelSize * (dsm.projection != DSM_PROJECTION_ORTHO ? distance(p, dsm.viewer) : 1.0);
    vec3 towardsLight = dsm.viewerIsPoint != 0u ? normalize(dsm.viewer - p) : dsm.viewer;
    vec3 q = p + (hair ? towardsLight : n) * (dsm.normalOffset * texel);
    vec4 clip = dsm.viewProj * vec4(q, 1.0);
    if (clip.w <= 0.0) return 1.0;
    const int res = int(dsm.resolution);
    const float width = dsm.filterWidth;
    vec2 s = (clip.xy / clip.w * 0.5 + 0.5) * float(res);  // texel i covers [i, i + 1)
    float d = dsmDepth(dsm.viewer, dsm.viewerIsPoint, q) - dsm.depthBias * texel;
    ivec2 lo = ivec2(floor(s - 0.5 * width - 0.5)), hi = ivec2(floor(s + 0.5 * width - 0.5)) + 1;
    uint base = uint(dsm.layer) * uint(res * res);
    float sum = 0.0;
    if (dsm.opacityMaps != 0u) {  // deep opacity map: the same taps, each read in place
        for (int y = max(lo.y, 0); y <= min(hi.y, res - 1); ++y)
            for (int x = max(lo.x, 0); x <= min(hi.x, res - 1); ++x)
                sum += dsmTapWeight(s.y, width, y) * dsmTapWeight(s.x, width, x) *
                       (domTransmittance(base + uint(y * res + x), d, dsm.layerThickness) - 1.0);
        return clamp(1.0 + sum, 0.0, 1.0);  // taps outside the map cast nothing (1 - 1 = 0 there)
    }
    if (dsm.binarySearch != 0u) return min(dsmSearchKernel(base, res, lo, hi, s, width, d), 1.0);
    uint rowHint = DSM_NONE;  // the upper link of the previous row's first node
    for (int y = lo.y; y <= hi.y; ++y) {
        float wy = dsmTapWeight(s.y, width, y);
        uint hint = rowHint, rowStart = DSM_NONE;
        for (int x = lo.x; x <= hi.x; ++x) {
            bool inside = x >= 0 && y >= 0 && x < res && y < res;  // outside the map: nothing casts
            uint node = inside ? dsmFind(base + uint(y * res + x), d, hint) : DSM_NONE;
            sum += wy * dsmTapWeight(s.x, width, x) * dsmTransmittanceOf(node);
            if (x == lo.x) rowStart = node;
            hint = node == DSM_NONE ? DSM_NONE : dsmNodes[node].w;
        }
        rowHint = rowStart == DSM_NONE ? DSM_NONE : dsmSide[rowStart];
    }
    return min(sum, 1.0);  // the weights sum to 1 up to rounding
}

// Transmittance AOV: the first light with a DSM, whether or not the receiver faces it.
float firstDeepShadowTransmittance(vec3 p, vec3 n, bool hair) {
    for (uint i = 0; i < frame.lightCount; ++i)
        if (dsmLights[i].layer >= 0) return deepShadowTransmittance(i, p, n, hair);
    return 1.0;
}

// Debug AOV: list length (after the resolve's cap) per texel of the first light with a DSM, its
// map stretched over the image (a deep opacity map: how many of its layers hold opacity); -1 when
// no light has one.
float dsmListLengthAov(ivec2 pixel, uvec2 size, uint lightCount) {
    for (uint i = 0; i < lightCount; ++i) {
        GpuDsmLight dsm = dsmLights[i];
        if (dsm.layer < 0) continue;
        uint res = dsm.resolution;
        uvec2 texel = min(uvec2(pixel) * res / size, uvec2(res - 1));
        uint index = uint(dsm.layer) * res * res + texel.y * res + texel.x;
        if (dsm.opacityMaps != 0u) {  // a deep opacity map: its layers holding opacity
            vec4 layers = uintBitsToFloat(dsmNodes[index]);
            return float(dsmHeads[index] != DSM_NONE) * dot(vec4(greaterThan(layers, vec4(0.0))), vec4(1.0));
        }
        uint n = dsmHeads[index * DSM_HEAD_UINTS];
        uint length = 0;
        for (; n != DSM_NONE && length < DSM_MAX_LIST_CAP; n = dsmNodes[n].z) ++length;
        return float(length);
    }
    return -1.0;
}
