#version 460
// Reflective shadow map (Dachsbacher & Stamminger 2005) resolved from the shadow pass's visibility
// IDs: per RSM texel, the depth, normal and flux of the surface the light sees there. No second
// raster of the light's view: the texel's ID comes from the ID layer (the shadow map's resolution;
// nearest ID texel to the RSM texel's centre), its attributes from the triangle at the texel's centre.
// The texel's footprint perpendicular to the light is A = t^2 for an orthographic map (t = texel
// world size) and A = t^2 z^2 cos(a) for a perspective one (t per unit depth, z the depth along the
// axis, a the angle off the axis: the texel's solid angle t^2 cos^3(a) times d^2). The flux through
// it is E_perp * A, and the surface reflects albedo times that (Lambertian).
#extension GL_GOOGLE_include_directive : require
#include "shared/types.h"
#include "rsm/bindings.h"
#include "core/material.glsl"
#include "core/lights.glsl"
#include "core/visibility.glsl"
#include "shared/octahedral.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = RSM_RESOLVE_LIGHTS, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = RSM_RESOLVE_LAYERS, std430) readonly buffer Layers { GpuRsmLayer rsmLayers[]; };
layout(set = 0, binding = RSM_RESOLVE_SHADOW_IDS) uniform usampler2DArray ids;
layout(set = 0, binding = RSM_RESOLVE_DEPTH, r32f) uniform writeonly image2DArray outDepth;
layout(set = 0, binding = RSM_RESOLVE_NORMAL, rg16_snorm) uniform writeonly image2DArray outNormal;
layout(set = 0, binding = RSM_RESOLVE_FLUX, rgba16f) uniform writeonly image2DArray outFlux;
// The same texel packed, for the gather's one fetch per VPL (rsm/vpl.glsl): depth bits, the
// normal's octahedral snorm16 pair, the flux's halves (r, g), (b, 0).
layout(set = 0, binding = RSM_RESOLVE_VPLS, rgba32ui) uniform writeonly uimage2DArray outVpls;
layout(push_constant) uniform Push { RsmResolvePush pc; };

void main() {
    const ivec3 texel = ivec3(gl_GlobalInvocationID);
    const uint res = pc.rsmResolution, idRes = pc.idResolution;
    if (texel.x >= int(res) || texel.y >= int(res)) return;
    const ivec2 idTexel = min(ivec2((vec2(texel.xy) + 0.5) * float(idRes) / float(res)), ivec2(idRes - 1u));
    const uint id = texelFetch(ids, ivec3(idTexel, texel.z), 0).r;
    if (id == 0u) {
        imageStore(outDepth, texel, vec4(1.0));
        imageStore(outNormal, texel, vec4(0.0));
        imageStore(outFlux, texel, vec4(0.0));
        imageStore(outVpls, texel, uvec4(floatBitsToUint(1.0), 0u, 0u, 0u));
        return;
    }
    const GpuRsmLayer layer = rsmLayers[texel.z];
    VisRay centre, dx0, dx1, dy0, dy1;
    quadRays(layer.invViewProj, texel.xy, vec2(float(res)), centre, dx0, dx1, dy0, dy1);
    const VisTriangle tri = fetchTriangle(id);
    const VisSurface s = resolveSurface(tri, centre, dx0, dx1, dy0, dy1);
    const vec4 clip = layer.viewProj * vec4(s.position, 1.0);
    const GpuLight light = lights[layer.light];
    vec3 l;
    const vec3 e = incidentIrradiance(light, s.position, l);
    const float t = layer.texelSize;
    float area = t * t;
    if (layer.perspective != 0u) {  // the layer's own axis (spot cone, or a point light's cube face)
        const float z = clip.w;
        area *= z * z * clamp(z / max(length(s.position - light.position), 1e-6), 0.0, 1.0);
    }
    // The side the light sees (two-sided surfaces), by the triangle's own plane; the shading normal
    // turned to that side.
    const vec3 face = cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
    vec3 n = dot(face, face) > 0.0 ? normalize(face) : s.normal;
    if (dot(n, l) < 0.0) n = -n;
    const vec3 shadingNormal = dot(s.normal, n) < 0.0 ? -s.normal : s.normal;
    // The surface is lit as the lighting pass (and the path tracer) lights it, by its shading
    // normal's cosine, over the area the texel covers (the footprint over the plane's cosine); it
    // sends its light out by its plane's normal (the area it shows a direction). With one normal
    // for both, VC's backdrop, whose shading normals lean up to 60 degrees off its triangles, sent
    // 1.5x the path tracer's light.
    const float lit = max(dot(shadingNormal, l), 0.0) / max(dot(n, l), 1e-3);
    // Rounded once, as packed: the separate images then hold the packed texel's values exactly. A
    // half float holds at most 65504: a brighter texel (a strong sun over texels of many square
    // metres) is clamped there, not stored as infinity, which turned the indirect light NaN.
    const vec3 flux = min(surfaceBaseColor(s).rgb * e * (area * lit), vec3(65504.0));
    const uvec4 vpl = uvec4(floatBitsToUint(clip.z / clip.w), packSnorm2x16(octEncode(n)), packHalf2x16(flux.rg),
                            packHalf2x16(vec2(flux.b, 0.0)));
    imageStore(outDepth, texel, vec4(uintBitsToFloat(vpl.x)));
    imageStore(outNormal, texel, vec4(unpackSnorm2x16(vpl.y), 0.0, 0.0));
    imageStore(outFlux, texel, vec4(unpackHalf2x16(vpl.z), unpackHalf2x16(vpl.w).x, 1.0));
    imageStore(outVpls, texel, vpl);
}
