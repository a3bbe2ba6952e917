#version 460
// Culling of the compute rasterizer (src/raster): the drawn triangles in clusters of
// RASTER_SETUP_GROUP consecutive ones (SceneGpu::drawnTriangles: one mesh's triangles are
// consecutive), one workgroup per cluster. The workgroup takes the cluster's world-space box from its
// triangles' vertices this frame (instances may have moved), then tests the box against every layer
// drawn: a layer keeps the cluster unless all 8 corners lie outside one plane of its view volume (in
// clip space, so boxes crossing the eye plane are kept). The setup pass then sets up only the
// triangles of the kept (cluster, layer) pairs: each view touches what it can see.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"

layout(local_size_x = RASTER_SETUP_GROUP) in;

layout(set = 0, binding = 0, std430) readonly buffer Views { mat4 viewProj[]; } views;
#include "render/instances.glsl"
layout(set = 0, binding = 6, std430) buffer Counters { RasterCounters counters; };
layout(set = 0, binding = 7, std430) readonly buffer Vertices { float vertexData[]; };  // penumbra::Vertex
layout(set = 0, binding = 8, std430) readonly buffer Indices { uint indices[]; };
layout(set = 0, binding = 10, std430) readonly buffer Layers { RasterLayer rasterLayers[]; };
layout(set = 0, binding = 11, std430) readonly buffer DrawnTriangles { uvec2 drawnTriangles[]; };  // (instance, triangle)
layout(set = 0, binding = 19, std430) writeonly buffer ClusterList { uint clusterList[]; };  // cluster | row << 24
layout(push_constant) uniform Push { RasterPush push; };

const int kVertexFloats = 8;
shared vec3 boxLo[RASTER_SETUP_GROUP], boxHi[RASTER_SETUP_GROUP];

// Whether all corners of the box lie outside one plane of the clip volume (-w <= x, y <= w, 0 <= z <= w).
bool outside(mat4 viewProj, vec3 lo, vec3 hi) {
    uint mask = 0x3Fu;
    for (int c = 0; c < 8; ++c) {
        const vec4 p = viewProj * vec4((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y, (c & 4) != 0 ? hi.z : lo.z, 1.0);
        mask &= uint(p.x < -p.w) | uint(p.x > p.w) << 1 | uint(p.y < -p.w) << 2 | uint(p.y > p.w) << 3 |
               uint(p.z < 0.0) << 4 | uint(p.z > p.w) << 5;
    }
    return mask != 0u;
}

void main() {
    const uint lane = gl_LocalInvocationID.x, clusters = (push.target.z + RASTER_SETUP_GROUP - 1) / RASTER_SETUP_GROUP;
    for (uint cluster = gl_WorkGroupID.x; cluster < clusters; cluster += gl_NumWorkGroups.x) {
        const uint drawn = cluster * RASTER_SETUP_GROUP + lane;
        vec3 lo = vec3(1e30), hi = vec3(-1e30);
        if (drawn < push.target.z) {
            const uvec2 ref = drawnTriangles[drawn];
            for (int i = 0; i < 3; ++i) {
                const uint base = indices[ref.y * 3 + i] * kVertexFloats;
                const vec3 p = instanceWorld(int(ref.x), vec3(vertexData[base], vertexData[base + 1], vertexData[base + 2]));
                lo = min(lo, p), hi = max(hi, p);
            }
        }
        barrier();  // the previous cluster's boxes are read
        boxLo[lane] = lo, boxHi[lane] = hi;
        barrier();
        for (uint half_ = RASTER_SETUP_GROUP / 2; half_ > 0u; half_ >>= 1) {
            if (lane < half_) {
                boxLo[lane] = min(boxLo[lane], boxLo[lane + half_]);
                boxHi[lane] = max(boxHi[lane], boxHi[lane + half_]);
            }
            barrier();
        }
        for (uint row = lane; row < push.target.w; row += RASTER_SETUP_GROUP)
            if (!outside(views.viewProj[rasterLayers[row].info.x], boxLo[0], boxHi[0]))
                clusterList[atomicAdd(counters.clusters.x, 1u)] = cluster | row << 24;
    }
}
