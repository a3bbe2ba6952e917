#version 460
// --rsm-far flux, the CDF of the texels' flux luminance in Hilbert order (rsm/flux_luminance.glsl),
// cut into n runs of n texels (n: the resolution rounded up to a power of two). Step 0 (workgroup:
// run x, layer y): running sums along each run and the run's total. Step 1 (workgroup: layer x): the
// runs' totals become running sums in place, the last of them the layer's total.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "rsm/bindings.h"

layout(local_size_x = 256) in;

layout(set = 0, binding = RSM_FLUX_VPLS) uniform usampler2DArray rsmVpls;
// [layer][run][i]: inclusive sums along each run; then [layer][run]: the runs' totals, then sums.
layout(set = 0, binding = RSM_FLUX_SUMS, std430) buffer Sums { float sums[]; };
layout(push_constant) uniform Push { RsmFluxPush pc; };

#include "rsm/flux_luminance.glsl"

shared float scan[256];

// Inclusive prefix sum of `value` over the workgroup (Hillis-Steele); `total`: the whole sum.
float workgroupScan(float value, out float total) {
    const uint lane = gl_LocalInvocationID.x;
    scan[lane] = value;
    barrier();
    for (uint step = 1u; step < 256u; step *= 2u) {
        const float add = lane >= step ? scan[lane - step] : 0.0;
        barrier();
        scan[lane] += add;
        barrier();
    }
    const float sum = scan[lane];
    total = scan[255];
    barrier();
    return sum;
}

float value(uint i) {
    const uint res = pc.rsmResolution, n = pc.curve;
    if (pc.step == 1u) return sums[pc.layerCount * n * n + gl_WorkGroupID.x * n + i];
    const uvec2 t = hilbertTexel(n, gl_WorkGroupID.x * n + i);
    if (any(greaterThanEqual(t, uvec2(res)))) return 0.0;
    return packedFluxLuminance(texelFetch(rsmVpls, ivec3(t, gl_WorkGroupID.y), 0));
}

void main() {
    const uint n = pc.curve, layer = pc.step == 1u ? gl_WorkGroupID.x : gl_WorkGroupID.y;
    const uint totals = pc.layerCount * n * n + layer * n;
    const uint out0 = pc.step == 1u ? totals : (layer * n + gl_WorkGroupID.x) * n;
    float carry = 0.0;
    for (uint i0 = 0u; i0 < n; i0 += 256u) {
        const uint i = i0 + gl_LocalInvocationID.x;
        const float v = i < n ? value(i) : 0.0;
        barrier();  // step 1 reads and writes the same words
        float total;
        const float sum = carry + workgroupScan(v, total);
        if (i < n) sums[out0 + i] = sum;
        carry += total;
    }
    if (pc.step == 0u && gl_LocalInvocationID.x == 0u) sums[totals + gl_WorkGroupID.x] = carry;
}
