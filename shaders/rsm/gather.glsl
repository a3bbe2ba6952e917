// RSM indirect gather: for a receiver, sum the irradiance of VPLs around its projection into each
// RSM layer, at the polar sample offsets of Dachsbacher & Stamminger (r_max * xi1 * (sin, cos)(2 pi
// xi2), generated once from a seed on the CPU with their density-compensating weights), or over
// every texel (exact mode, for tests). Writes irradiance; lighting multiplies by albedo / pi.
// Four pipelines, so that the default one stays lean: rsm/gather_flux.comp (RSM_FAR_FLUX and
// RSM_SHIFTED_RADII: the default), gather.comp (the far disc with fixed radii, the seed's way),
// gather_shifted.comp (RSM_SHIFTED_RADII: every other choice, told by the push constants) and
// gather_voxels.comp (that and RSM_VOXEL_VISIBILITY).
#include "shared/types.h"
#include "rsm/bindings.h"
#include "core/lights.glsl"
#include "core/reconstruct.glsl"
#include "shared/hash.glsl"
#include "shared/luminance.glsl"
#include "shared/gi_change.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = RSM_GATHER_FRAME) uniform Frame { FrameUniforms frame; };
layout(set = 0, binding = RSM_GATHER_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(set = 0, binding = RSM_GATHER_GBUFFER_DEPTH) uniform sampler2D gDepth;
layout(set = 0, binding = RSM_GATHER_RSM_DEPTH) uniform sampler2DArray rsmDepth;
layout(set = 0, binding = RSM_GATHER_RSM_NORMAL) uniform sampler2DArray rsmNormal;
layout(set = 0, binding = RSM_GATHER_RSM_FLUX) uniform sampler2DArray rsmFlux;
layout(set = 0, binding = RSM_GATHER_LAYERS, std430) readonly buffer Layers { GpuRsmLayer rsmLayers[]; };
layout(set = 0, binding = RSM_GATHER_SAMPLES, std430) readonly buffer Samples { vec4 samples[]; };  // two per sample (rsm_gather.cpp)
layout(set = 0, binding = RSM_GATHER_IRRADIANCE, rgba32f) uniform writeonly image2D outIrradiance;
layout(set = 0, binding = RSM_GATHER_PIXEL_LIST, std430) readonly buffer PixelList { uvec4 header; uvec2 pixels[]; } list;
layout(set = 0, binding = RSM_GATHER_VPLS) uniform usampler2DArray rsmVpls;  // depth, normal and flux in one texel
layout(set = 0, binding = RSM_GATHER_FLUX_DRAWS, std430) readonly buffer FluxDrawBuffer { uvec4 blocks[]; } drawn;  // shared/types.h
layout(set = 0, binding = RSM_GATHER_GRADIENT_SAMPLES, std430) buffer GradientSamples { GpuGradientSample gradientSamples[]; };
layout(push_constant) uniform Push { RsmPush pc; };

#include "rsm/vpl.glsl"
#include "rsm/flux_luminance.glsl"
#ifdef RSM_VOXEL_VISIBILITY
#define OCCUPANCY_BINDING RSM_GATHER_OCCUPANCY
#include "voxel/occupancy.glsl"
#endif

// Centre and radius of the sampling disc for receiver x. The pattern is centred on x's projection.
// A receiver outside the map (for a spot light: outside its pyramid, or behind it, like a ceiling
// above a downward spot) has no texel of its own: its disc starts at the map border in x's direction
// and, as x leaves the map (angle off the axis for a spot, uv distance for an orthographic map),
// slides to the map centre while growing to the whole map. The result stays continuous across the
// frustum's border, and the weights scale with the disc's area, so the estimate keeps converging to
// the sum over its disc. `clip`: x in the layer's clip space.
float samplingDisc(GpuRsmLayer layer, vec4 clip, out vec2 st) {
    const float rMax = pc.radius, whole = max(rMax, 0.70710678);
    float outside;
    vec2 border;
    if (layer.perspective != 0u) {
        float m = max(abs(clip.x), abs(clip.y));
        float angle = atan(m, clip.w);  // 0 on the axis, pi/4 at the map's border, pi straight behind
        if (angle <= 0.78539816) {
            st = clip.xy / clip.w * 0.5 + 0.5;
            return rMax;
        }
        border = 0.5 + 0.5 * clip.xy / m;
        outside = (angle - 0.78539816) / 2.35619449;
    } else {
        vec2 p = clip.xy / clip.w * 0.5 + 0.5;
        border = clamp(p, vec2(0.0), vec2(1.0));
        if (border == p) {
            st = p;
            return rMax;
        }
        outside = min(2.0 * length(p - border), 1.0);
    }
    st = mix(border, vec2(0.5), outside);
    return mix(rMax, whole, outside);
}

// Per-receiver rotation and radial shift of the sample pattern, seeded by the receiver's world
// position (quantised to RSM texels): neighbouring receivers see different VPLs, so the
// interpolation's filter averages independent estimates, and the pattern of a surface point stays
// put when the camera moves. While the temporal-GI module accumulates, the seed also changes each
// frame (pc.frameSeed), so that the history averages independent estimates of every point.
uint hash3(uvec3 v) { return hashMix(v.x * 0x8da6b343u ^ v.y * 0xd8163841u ^ v.z * 0xcb1ab31fu); }

struct ReceiverPattern {
    mat2 rotation;
    float shift;  // added to xi1, modulo 1
};

ReceiverPattern receiverPattern(GpuRsmLayer L, vec3 x, vec4 clip) {
    float texel = L.texelSize;
    if (L.perspective != 0u) texel *= max(abs(clip.w), 1e-3);
    ReceiverPattern p;
    uint seed = hash3(uvec3(ivec3(floor(x / texel))));
    if (pc.frameSeed != 0u) seed = hashMix(seed ^ hashMix(pc.frameSeed));  // another pattern each frame
    const float angle = float(seed) * (6.28318531 / 4294967296.0), c = cos(angle), s = sin(angle);
    p.rotation = mat2(c, s, -s, c);
    p.shift = float(hash3(uvec3(seed, 0x9e3779b9u, 1u))) * (1.0 / 4294967296.0);
    return p;
}

// Whether a point at depth z lies behind the surface a depth map holds there (`seen`), past a margin
// that grows towards the far plane, where a perspective depth's steps grow; `floorBias` is the margin at
// the far plane.
bool behindSurface(float z, float seen, float floorBias) { return z > seen + 0.01 * (1.0 - seen) + floorBias; }

// Whether the camera's depth buffer hides a point (`c`: its camera clip position). Outside the
// camera's view it knows nothing: hidden, so that the light's verdict stands (taking such points as
// seen left Sponza +29% bright against +21%).
bool hiddenFromCamera(vec4 c) {
    if (c.w <= 0.0) return true;
    const vec3 p = c.xyz / c.w;
    if (any(greaterThan(abs(p.xy), vec2(1.0)))) return true;
    const ivec2 pixel = min(ivec2((p.xy * 0.5 + 0.5) * vec2(frame.width, frame.height)), ivec2(frame.width, frame.height) - 1);
    return behindSurface(p.z, texelFetch(gDepth, pixel, 0).r, 1e-5);
}

// Whether the RSM layer's depth hides a point (`c`: its clip position in the layer): it lies in the
// shadow of the surface the light sees there. Off the map: not hidden.
bool hiddenFromLight(vec4 c, bool perspective, uint layer, int res) {
    if (c.w <= 0.0) return false;
    const vec3 p = perspective ? c.xyz / c.w : c.xyz;  // an orthographic layer's w is 1
    const vec2 uv = p.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return false;
    return behindSurface(p.z, texelFetch(rsmDepth, ivec3(ivec2(uv * float(res)), layer), 0).r, 1e-4);
}

// Whether the VPL of texel t (RSM depth `depth`) sees x, tested at points of the segment between them
// against the depth maps at hand. A point behind the surface the light sees where it projects lies in
// that surface's shadow.
// - RSM_VISIBILITY_DEPTH (far samples only): two points, 0.3 and 0.6 of the way from the VPL (one
//   nearer x finds x's own shadow, not an occluder); a point in shadow is solid.
// - RSM_VISIBILITY_VIEWS (every sample): pc.visibilityPoints points spread evenly over 0.05-0.95 of the way,
//   their offset `jitter` per sample; a point in shadow is solid only where the camera's surface hides
//   it too. Air in a shadow (a street's, a receiver's own) is seen by the camera; the inside of a wall
//   or floor is seen by neither view. A thin occluder between two points is missed; jittered points
//   catch it in a share of the samples.
// Projection is linear in homogeneous coordinates: the VPL's clip position is its texel's NDC over
// the w its unprojection divides by, and x's (`clipX`, `camX`) is the receiver's, so each point's
// clip position is a mix of the two, with no matrix per point.
float segmentVisibility(GpuRsmLayer L, uint layer, ivec2 t, float depth, vec4 clipX, vec4 camX, float jitter) {
    if (depth >= 1.0) return 1.0;
    const int res = int(pc.rsmResolution);
    const bool views = pc.visibility == RSM_VISIBILITY_VIEWS;
    const vec4 ndc = vec4((vec2(t) + 0.5) / float(res) * 2.0 - 1.0, depth, 1.0);
    const vec4 clipP = ndc / dot(vec4(L.invViewProj[0].w, L.invViewProj[1].w, L.invViewProj[2].w, L.invViewProj[3].w), ndc);
    const uint points = views ? pc.visibilityPoints : 2u;
    const float step = views ? 0.9 / float(points) : 0.3, first = views ? 0.05 + step * jitter : 0.3;
    vec4 camP = vec4(0.0);  // the VPL in the camera's clip space, once a point needs it
    for (uint k = 0u; k < points; ++k) {
        const float a = first + step * float(k);
        if (!hiddenFromLight(mix(clipP, clipX, a), L.perspective != 0u, layer, res)) continue;
        if (!views) return 0.0;
        if (camP.w == 0.0) camP = frame.viewProj * (L.invViewProj * clipP);
        if (hiddenFromCamera(mix(camP, camX, a))) return 0.0;
    }
    return 1.0;
}

// Sample i of the pattern (src/rsm/rsm_gather.cpp) for a receiver that shifts xi1 by `shift`: its
// offset in uv (for the r_max the pattern was made with), its weight in texels (1 / (N density)),
// and 1 beyond r_max. The mixture's polar discs (radius xi1 R: area density 1 / (2 pi r R) on the
// disc) are unbiased for any shift. Shifted per receiver (--rsm-radii shifted), the radii differ
// between receivers; one set of radii for all (fixed, shift 0) is a fixed quadrature of the 1/d^2
// near field, dark by 8% at 400 samples on cornell (15% at 100). The paper's disc keeps its xi1^2
// weights (E[xi1^2] = 1/3).
vec4 patternSample(uint i, float shift) {
    const vec4 p = samples[pc.sampleCount + i];
    const float rMax = pc.radius, texels = float(pc.rsmResolution * pc.rsmResolution), n = float(pc.sampleCount);
    if (pc.paperWeights != 0u) return vec4(p.z * rMax * p.xy, PI * rMax * rMax * texels / n * 3.0 * p.z * p.z, 0.0);
    const float whole = max(rMax, 1.41421356), r = max(fract(p.z + shift), 1e-6) * p.w;
    const float density = (0.5 / whole + (r < rMax ? 0.5 / rMax : 0.0)) / (2.0 * PI * r);
    return vec4(r * p.xy, texels / (n * density), r > rMax ? 1.0 : 0.0);
}

// --rsm-far flux: of a receiver's N samples, the n_near = N - N/2 of even index lie on the r_max disc
// (radius R = r_max * scale around the receiver's projection, polar: p_near = 1 / (2 pi r R) per uv
// area) and the n_far = N/2 of odd index are texels drawn by flux luminance (p_far = lum / total,
// rsm/flux_draw.comp). Either kind weighs its texel by the balance heuristic, 1 / (n_near p_near +
// n_far p_far), both per texel: unbiased over every texel with flux, and no sample is spent on a
// dark one. rsm/gather_flux.comp (the default: shifted radii) compiles it in (RSM_FAR_FLUX), the
// shifted and voxel pipelines ask the push constants, and rsm/gather.comp (the far disc with fixed
// radii) leaves it out.
#if defined(RSM_FAR_FLUX)
#define FLUX_FAR true
#elif defined(RSM_SHIFTED_RADII)
#define FLUX_FAR (pc.farByFlux != 0u)
#else
#define FLUX_FAR false
#endif

struct FluxDraws {
    uint block;          // the layer's block of drawn.blocks
    float farPerLum;     // n_far / total: n_far p_far per unit of flux luminance
    float nearRate;      // n_near / (2 pi R texels): n_near p_near times r
    float radius;        // R, uv units
    float stride;        // entries per far sample
};

FluxDraws layerDraws(uint layer, float scale) {
    FluxDraws d;
    const uint n = pc.sampleCount;
    d.block = layer * RSM_FLUX_BLOCK;
    const float total = FLUX_FAR ? uintBitsToFloat(drawn.blocks[d.block].x) : 0.0;
    d.farPerLum = total > 0.0 ? float(n / 2u) / total : 0.0;
    d.radius = pc.radius * scale;
    d.nearRate = float(n - n / 2u) / (2.0 * PI * d.radius * float(pc.rsmResolution * pc.rsmResolution));
    d.stride = float(RSM_FLUX_ENTRIES) / max(float(n / 2u), 1.0);
    return d;
}

// Far sample k of a receiver whose offset in [0, 1) is `shift`: entry (k + shift) K / n_far, so that
// its n_far draws are stratified over the layer's CDF, and receivers with other offsets draw others.
uint fluxEntry(FluxDraws d, uint k, float shift) {
    return min(uint((float(k) + shift) * d.stride), RSM_FLUX_ENTRIES - 1u);
}

ivec2 fluxTexel(FluxDraws d, uint entry) {
    const uint word = drawn.blocks[d.block + 3u + 2u * entry].x;
    return ivec2(word & 0xFFFFu, word >> 16);
}

// The balance heuristic's weight of a texel whose packed VPL is `vpl`, at uv distance r from the
// disc's centre.
float balanceWeight(FluxDraws d, float r, uvec4 vpl) {
    const float density = (r < d.radius ? d.nearRate / max(r, 1e-7) : 0.0) + d.farPerLum * packedFluxLuminance(vpl);
    return density > 0.0 ? 1.0 / density : 0.0;
}

#ifdef RSM_VOXEL_VISIBILITY
// Visibility of the VPL of texel t from x through the occupancy volume: the segment between them,
// each end lifted off its own surface (x along its normal, or towards the VPL for a hair strand; the
// VPL along its normal), must cross no occupied voxel beyond kVisibilitySkip voxels from either end.
// A surface occupies the voxels it meets, which reach up to sqrt(3) voxels from it along its normal
// (a voxel's extent along n is |n|_1 <= sqrt(3)): lifted by more, an end clears its own surface; the
// skip clears the shells of surfaces beside it (a receiver in a corner). Against Embree-traced
// visibility: within 2-4% (tests/rsm_visibility_test.cpp).
const float kVisibilityLift = 1.8;
const float kVisibilitySkip = 1.5;

float voxelVisibility(uint layer, ivec2 t, vec3 x, vec3 n, bool hair) {
    const float depth = texelFetch(rsmDepth, ivec3(t, layer), 0).r;
    if (depth >= 1.0) return 1.0;
    const vec3 position = vplPosition(t, layer, depth);
    const vec3 normal = octDecode(texelFetch(rsmNormal, ivec3(t, layer), 0).xy);
    const float lift = kVisibilityLift * occupancyVoxelSize();
    const vec3 a = x + lift * (hair ? normalize(position - x) : n);
    return segmentClear(a, position + lift * normal, kVisibilitySkip) ? 1.0 : 0.0;
}
#endif

// The four VPLs around RSM position uv, weighted bilinearly: the same expected light as the texel uv
// falls in, but continuous in uv, so that it does not jump when the texel lattice moves under a sample.
vec3 bilinearVplIrradiance(vec2 uv, int res, uint layer, vec3 x, vec3 n, bool hair) {
    const vec2 f = uv * float(res) - 0.5;
    const ivec2 t0 = ivec2(floor(f));
    const vec2 w = f - vec2(t0);
    vec3 e = vec3(0.0);
    for (int k = 0; k < 4; ++k) {
        const ivec2 o = ivec2(k & 1, k >> 1);
        const float weight = (o.x == 1 ? w.x : 1.0 - w.x) * (o.y == 1 ? w.y : 1.0 - w.y);
        e += weight * vplIrradiance(clamp(t0 + o, ivec2(0), ivec2(res - 1)), layer, x, n, hair);
    }
    return e;
}

// The exact sum over every texel of a layer (RSM_GATHER_ALL_TEXELS, for tests), this lane's share.
vec3 exactLayerSum(GpuRsmLayer L, uint layer, vec3 x, vec3 n, bool hair, vec4 clipX, vec4 camX, uint lane, uint lanes) {
    const int res = int(pc.rsmResolution);
    vec3 e = vec3(0.0);
    for (uint k = lane; k < uint(res * res); k += lanes) {
        const ivec2 t = ivec2(k % uint(res), k / uint(res));
        const uvec4 vpl = texelFetch(rsmVpls, ivec3(t, layer), 0);
        vec3 c = vplIrradianceOf(vpl, t, layer, x, n, hair);
        if (pc.visibility == RSM_VISIBILITY_VIEWS && any(greaterThan(c, vec3(0.0))))
            c *= segmentVisibility(L, layer, t, uintBitsToFloat(vpl.x), clipX, camX, fract(float(k) * 0.61803399));
#ifdef RSM_VOXEL_VISIBILITY
        if (any(greaterThan(c, vec3(0.0)))) c *= voxelVisibility(layer, t, x, n, hair);
#endif
        e += c;
    }
    return e;
}

// `lane` of `lanes` invocations that share the receiver: each sums its share of the samples (or
// texels) and main() adds the lanes' sums.
vec3 gather(vec3 x, vec3 n, bool hair, uint lane, uint lanes) {
    vec3 e = vec3(0.0);
    const int res = int(pc.rsmResolution);
    const bool views = pc.visibility == RSM_VISIBILITY_VIEWS;
    const vec4 camX = views ? frame.viewProj * vec4(x, 1.0) : vec4(0.0);  // x in the camera's clip space
    uint usedCascadeLight = 0xFFFFFFFFu;
    for (uint layer = 0; layer < pc.layerCount; ++layer) {
        // Cascades of a light: the first whose map holds x, else the last (seed: SearchCascadeIndex).
        GpuRsmLayer L = rsmLayers[layer];
        const vec4 clipX = L.viewProj * vec4(x, 1.0);  // x in the layer's clip space
        if (L.cascade != 0u) {
            if (L.light == usedCascadeLight) continue;
            if (L.lastCascade == 0u && any(greaterThan(abs(clipX.xy / clipX.w), vec2(1.0)))) continue;
            usedCascadeLight = L.light;
        }
        if (pc.mode == RSM_GATHER_ALL_TEXELS) {
            e += exactLayerSum(L, layer, x, n, hair, clipX, camX, lane, lanes);
            continue;
        }
        vec2 st;
        float scale = samplingDisc(L, clipX, st) * L.radiusScale / pc.radius;
        const ReceiverPattern pattern = receiverPattern(L, x, clipX);
        // Voxel visibility: every stride-th sample walks the occupancy volume; the visible share of
        // those samples' light scales the layer's light. The same samples for every receiver: the
        // lanes of a subgroup walk together (a per-receiver choice made each walk wait for up to
        // `stride` others', several times the cost). The pattern's rotation and shift still differ.
        const uint stride = max(pc.sampleCount / max(pc.visibilityRays, 1u), 1u) | 1u;  // odd: both discs' samples
        vec3 layerLight = vec3(0.0);
        vec2 tested = vec2(0.0);  // luminance of the tested samples' light: all of it, the visible part
        // A lane takes a run of consecutive samples, of even length: the pattern alternates its two
        // discs, and lanes that stepped by `lanes` would split a warp between near samples and far
        // ones (which alone test visibility) at every step.
        const uint run = (pc.sampleCount + 2u * lanes - 1u) / (2u * lanes) * 2u;
        const FluxDraws draws = layerDraws(layer, scale);
        for (uint i = lane * run, end = min(i + run, pc.sampleCount); i < end; ++i) {
            vec3 c;
            ivec2 t;
            uvec4 vpl;  // the texel's packed VPL (its depth in x)
            float weight;
            bool far;
            if (FLUX_FAR && (i & 1u) == 1u) {  // the far half: a texel drawn by flux
                const uint entry = fluxEntry(draws, i >> 1u, pattern.shift);
                vpl = drawn.blocks[draws.block + 2u + 2u * entry];
                t = fluxTexel(draws, entry);
                const float r = length((vec2(t) + 0.5) / float(res) - st);
                weight = balanceWeight(draws, r, vpl);
                far = r >= draws.radius;
                c = vplIrradianceOf(vpl, t, layer, x, n, hair);
            } else {
#ifdef RSM_SHIFTED_RADII
                vec4 s = patternSample(i, pc.shiftedRadii != 0u ? pattern.shift : 0.0);  // 0: fixed radii
#else
                vec4 s = samples[i];
#endif
                const vec2 uv = st + pattern.rotation * s.xy * scale;
                if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) continue;
                t = ivec2(uv * float(res));
                vpl = texelFetch(rsmVpls, ivec3(t, layer), 0);
                weight = FLUX_FAR ? balanceWeight(draws, length(s.xy) * scale, vpl) : s.z * scale * scale;
                far = !FLUX_FAR && s.w > 0.5;
                c = pc.bilinearVpls != 0u ? bilinearVplIrradiance(uv, res, layer, x, n, hair) : vplIrradianceOf(vpl, t, layer, x, n, hair);
            }
            if ((views || (pc.visibility == RSM_VISIBILITY_DEPTH && far)) && any(greaterThan(c, vec3(0.0))))
                c *= segmentVisibility(L, layer, t, uintBitsToFloat(vpl.x), clipX, camX,
                                       fract(pattern.shift * 13.0 + float(i) * 0.61803399));
            c *= weight;
#ifdef RSM_VOXEL_VISIBILITY
            if (i % stride == 0u) {
                const float lum = luminance(c);
                tested += vec2(lum, lum * voxelVisibility(layer, t, x, n, hair));
            }
#endif
            layerLight += c;
        }
        e += tested.x > 0.0 ? layerLight * (tested.y / tested.x) : layerLight;
    }
    return e;
}

// A receiver: a surface point, its normal (facing the eye) or a strand's tangent.
struct Receiver {
    vec3 x;
    vec3 n;
    bool hair;
    bool exists;
};

Receiver pixelReceiver(ivec2 pixel) {
    Receiver r = Receiver(vec3(0.0), vec3(0.0), false, false);
    const float depth = texelFetch(gDepth, pixel, 0).r;
    if (depth >= 1.0) return r;
    r.x = pixelWorldPosition(frame, pixel, depth);
    const vec4 g = texelFetch(gNormal, pixel, 0);
    r.n = normalize(g.xyz);
    r.hair = g.w > 1.5;  // SHADING_HAIR (--translucency off): n is the strand's tangent
    if (!r.hair && dot(r.n, frame.eye - r.x) < 0.0) r.n = -r.n;
    r.exists = true;
    return r;
}

// RSM_GATHER_LOWRES: the cell pc.gradientPhase - 1 of each 2x2 block keeps its receiver and its
// light for the next frame's gradient (the block's last cell where the grid ends inside it).
void keepGradientSample(ivec2 cell, Receiver r, vec3 e) {
    if (pc.gradientPhase == 0u) return;
    const ivec2 block = cell / 2, offset = ivec2((pc.gradientPhase - 1u) & 1u, (pc.gradientPhase - 1u) >> 1u);
    if (cell != min(block * 2 + offset, ivec2(pc.width, pc.height) - 1)) return;
    const uint index = uint(block.y) * ((pc.width + 1u) / 2u) + uint(block.x);
    gradientSamples[index] = GpuGradientSample(r.x, r.exists ? luminance(e) : -1.0, r.n, r.hair ? 1u : 0u);
}

// RSM_GATHER_GRADIENT: the change of a kept sample's luminance, written where its point is seen now
// (forward projection: the samples' image was cleared).
void storeGradient(Receiver r, float before, vec3 e) {
    const vec4 c = frame.viewProj * vec4(r.x, 1.0);
    if (c.w <= 0.0) return;
    const vec2 uv = c.xy / c.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return;
    const ivec2 texel = ivec2(uv * vec2(frame.width, frame.height)) / int(pc.lowResFactor * pc.gradientPhase);
    imageStore(outIrradiance, texel, giChangeTexel(luminance(e), before));
}

// Receivers share out their samples: `lanes` (push sampling.w: 1, 2, 4 or 8) invocations of a
// workgroup per receiver, each summing a run of consecutive samples, their sums added in shared memory. The
// fallback list is a few percent of the pixels: one invocation each leaves most of a large GPU's
// multiprocessors waiting on memory. The voxel pipeline keeps one lane:
// its visible share is a ratio per receiver and layer.
shared vec3 laneSums[64];

void main() {
    const uint lanes = max(pc.lanesPerReceiver, 1u), local = gl_LocalInvocationIndex, lane = local % lanes;
    const uint receiver = local / lanes, perGroup = 64u / lanes;
    ivec2 out_;
    bool valid;
    if (pc.mode == RSM_GATHER_LIST) {
        const uint group = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
        const uint index = group * perGroup + receiver;
        valid = index < list.header.x;
        out_ = valid ? ivec2(list.pixels[index]) : ivec2(0);
    } else {  // a workgroup covers 8 x (8 / lanes) receivers
        out_ = ivec2(gl_WorkGroupID.xy) * ivec2(8, perGroup / 8u) + ivec2(receiver % 8u, receiver / 8u);
        valid = all(lessThan(out_, ivec2(pc.width, pc.height)));
    }
    Receiver r = Receiver(vec3(0.0), vec3(0.0), false, false);
    float before = -1.0;  // RSM_GATHER_GRADIENT: the kept sample's luminance last frame
    if (valid && pc.mode == RSM_GATHER_GRADIENT) {
        const GpuGradientSample s = gradientSamples[uint(out_.y) * pc.width + uint(out_.x)];
        before = s.luminance;
        r = Receiver(s.position, s.normal, s.hair != 0u, s.luminance >= 0.0);
    } else if (valid) {
        ivec2 pixel = out_;
        if (pc.mode == RSM_GATHER_LOWRES)  // the cell's representative (centre) full-res pixel
            pixel = min(out_ * int(pc.lowResFactor) + int(pc.lowResFactor) / 2, ivec2(frame.width, frame.height) - 1);
        r = pixelReceiver(pixel);
    }
    vec3 e = r.exists ? gather(r.x, r.n, r.hair, lane, lanes) : vec3(0.0);
    if (lanes > 1u) {
        laneSums[local] = e;
        barrier();
        for (uint step = lanes / 2u; step > 0u; step /= 2u) {
            if (lane < step) laneSums[local] += laneSums[local + step];
            barrier();
        }
        e = laneSums[local];
    }
    if (!valid || lane != 0u) return;
    if (pc.mode == RSM_GATHER_GRADIENT) {
        if (r.exists) storeGradient(r, before, e);
        return;
    }
    imageStore(outIrradiance, out_, vec4(e, 1.0));
    if (pc.mode == RSM_GATHER_LOWRES) keepGradientSample(out_, r, e);
}
