#version 460
// RSM down-sampling for LPV injection (Kaplanyan 2010): in each block of RSM texels keep the
// brightest one (luminance of its flux times max(0, n.l)) and merge only the texels whose LPV cell
// lies in the 26-neighbourhood of the brightest texel's cell, so that one VPL never smears light
// across a depth discontinuity. Merged: position and normal averaged, flux and surfel area summed.
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "lpv/bindings.h"
#include "core/lights.glsl"
#include "core/reconstruct.glsl"
#include "shared/octahedral.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = LPV_DOWNSAMPLE_RSM_DEPTH) uniform sampler2DArray rsmDepth;
layout(set = 0, binding = LPV_DOWNSAMPLE_RSM_NORMAL) uniform sampler2DArray rsmNormal;
layout(set = 0, binding = LPV_DOWNSAMPLE_RSM_FLUX) uniform sampler2DArray rsmFlux;
layout(set = 0, binding = LPV_DOWNSAMPLE_LAYERS, std430) readonly buffer Layers { GpuRsmLayer rsmLayers[]; };
layout(set = 0, binding = LPV_DOWNSAMPLE_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = LPV_DOWNSAMPLE_VPLS, std430) writeonly buffer Vpls { GpuVpl vpls[]; };
layout(push_constant) uniform Push { LpvPush pc; };

#include "lpv/volume.glsl"

struct Texel {
    vec3 position, normal, flux;
    float area, brightness;
    bool valid;
};

Texel readTexel(ivec2 t, uint layer) {
    Texel r;
    float depth = texelFetch(rsmDepth, ivec3(t, layer), 0).r;
    r.valid = depth < 1.0;
    if (!r.valid) return r;
    GpuRsmLayer L = rsmLayers[layer];
    r.position = unproject(L.invViewProj, (vec2(t) + 0.5) / float(pc.rsmResolution), depth);
    r.normal = octDecode(texelFetch(rsmNormal, ivec3(t, layer), 0).xy);
    r.flux = texelFetch(rsmFlux, ivec3(t, layer), 0).rgb;
    vec3 l;
    incidentIrradiance(lights[L.light], r.position, l);
    float cosine = max(dot(r.normal, l), 0.0);
    // Surfel area on the surface: the texel's footprint across the light over the incidence cosine.
    float t2 = L.texelSize * L.texelSize;
    if (L.perspective != 0u) {
        float z = abs((L.viewProj * vec4(r.position, 1.0)).w);
        t2 *= z * z;
    }
    r.area = t2 / max(cosine, 0.2);
    r.brightness = dot(r.flux, vec3(0.2126, 0.7152, 0.0722)) * cosine;
    return r;
}

// The cell of x in the finest cascade that holds it (the 26-neighbourhood test is done there).
ivec3 finestCell(vec3 x, out uint cascade) {
    for (cascade = 0; cascade + 1 < pc.cascadeCount; ++cascade)
        if (insideGrid(ivec3(floor(gridCoord(cascade, x))))) break;
    return ivec3(floor(gridCoord(cascade, x)));
}

void main() {
    uvec3 id = gl_GlobalInvocationID;
    uint ds = pc.vplResolution;
    if (id.x >= ds || id.y >= ds) return;
    int block = int(pc.rsmResolution / ds);
    ivec2 base = ivec2(id.xy) * block;
    int brightest = -1;
    float best = -1.0;
    for (int i = 0; i < block * block; ++i) {
        Texel t = readTexel(base + ivec2(i % block, i / block), id.z);
        if (t.valid && t.brightness > best) best = t.brightness, brightest = i;
    }
    GpuVpl v;
    v.position = vec3(0.0);
    v.exists = 0u;
    v.normal = vec3(0.0, 1.0, 0.0);
    v.area = 0.0;
    v.flux = vec3(0.0);
    v.pad0 = 0u;
    if (brightest >= 0) {
        Texel b = readTexel(base + ivec2(brightest % block, brightest / block), id.z);
        uint cascade;
        ivec3 cell = finestCell(b.position, cascade);
        vec3 position = vec3(0.0), normal = vec3(0.0), flux = vec3(0.0);
        float area = 0.0, count = 0.0;
        for (int i = 0; i < block * block; ++i) {
            Texel t = readTexel(base + ivec2(i % block, i / block), id.z);
            if (!t.valid) continue;
            ivec3 c = ivec3(floor(gridCoord(cascade, t.position)));
            if (any(greaterThan(abs(c - cell), ivec3(1)))) continue;
            position += t.position;
            normal += t.normal;
            flux += t.flux;
            area += t.area;
            count += 1.0;
        }
        v.position = position / count;
        v.exists = 1u;
        v.normal = length(normal) > 1e-6 ? normalize(normal) : b.normal;
        v.area = area;
        v.flux = flux;
    }
    vpls[(id.z * ds + id.y) * ds + id.x] = v;
}
