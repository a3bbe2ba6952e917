#version 460
// DSM neighbour links, after the resolve (every list sorted by depth): each node learns the node of
// the right (x + 1) and the upper (y + 1) texel's list with the largest depth <= its own (DSM_NONE
// when that list has none in front of it). Both lists are sorted, so one merge-like walk per
// neighbour finds every link. The lookup then moves between neighbouring texels of its filter
// kernel without walking their lists from the head.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "dsm/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = DSM_LINK_HEADS, std430) readonly buffer Heads { uint heads[]; };
layout(set = 0, binding = DSM_LINK_NODES, std430) buffer Nodes { uvec4 nodes[]; };
layout(set = 0, binding = DSM_LINK_UP_LINKS, std430) writeonly buffer UpLinks { uint upLinks[]; };  // the side buffer
layout(push_constant) uniform Push { DsmPush pc; };

float depthOf(uint n) { return uintBitsToFloat(nodes[n].x); }

// Links every node of the list at `head` into the list at `other`; `right` picks the link slot.
void link(uint head, uint other, bool right) {
    uint behind = DSM_NONE;  // last node of `other` with depth <= the current node's
    uint ahead = other;
    for (uint n = head; n != DSM_NONE; n = nodes[n].z) {
        float d = depthOf(n);
        while (ahead != DSM_NONE && depthOf(ahead) <= d) {
            behind = ahead;
            ahead = nodes[ahead].z;
        }
        if (right) nodes[n].w = behind;  // only .w is written here; neighbours read .x and .z
        else upLinks[n] = behind;
    }
}

void main() {
    const uint res = pc.resolution;
    uvec3 id = gl_GlobalInvocationID;
    if (id.x >= res || id.y >= res) return;
    uint texel = (id.z * res + id.y) * res + id.x;
    uint head = heads[texel * DSM_HEAD_UINTS];  // the resolved list (shared/types.h)
    if (head == DSM_NONE) return;
    link(head, id.x + 1 < res ? heads[(texel + 1) * DSM_HEAD_UINTS] : DSM_NONE, true);
    link(head, id.y + 1 < res ? heads[(texel + res) * DSM_HEAD_UINTS] : DSM_NONE, false);
}
