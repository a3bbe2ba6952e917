// The DSM build's one job per light-space fragment: allocate a node from the pool (one atomic add)
// and push it onto the texel's list (one atomic exchange, one store). Needs `draw` (HairDrawPush).
// A full pool drops the fragment; the counter keeps counting, so the overflow is known exactly and
// no list ever points at a node that was not written.
layout(set = 0, binding = 5, std430) buffer Heads { uint heads[]; };
layout(set = 0, binding = 6, std430) writeonly buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = 7, std430) buffer Stats { DsmStats stats; };

void dsmInsert(float depth, float alpha) {
    if (alpha <= 0.0) return;  // nothing to cast
    uint node = atomicAdd(stats.build.x, 1u);
    if (node >= draw.ids.w) return;
    uint res = uint(draw.footprint.z);
    uvec2 texel = uvec2(gl_FragCoord.xy);
    uint previous = atomicExchange(heads[(draw.ids.z * res + texel.y) * res + texel.x], node);
    nodes[node] = uvec4(floatBitsToUint(depth), floatBitsToUint(min(alpha, 1.0)), previous, DSM_NONE);
}
