// Struct layouts shared by C++ and GLSL (std430 / std140-safe: mat4, vec4, a vec3 always followed
// by a 4-byte scalar, and scalars in groups of four). Included by C++ (namespace penumbra::gpu) and by GLSL (#include "shared/types.h").
#ifndef PENUMBRA_SHARED_TYPES_H
#define PENUMBRA_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
namespace penumbra::gpu {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = uint32_t;
#endif

// Light types (GpuLight.type).
#define LIGHT_DIRECTIONAL 0
#define LIGHT_SPOT 1
#define LIGHT_POINT 2

// Output selections (FrameUniforms.aov). Radiance AOVs are tone-mapped for PNG, data AOVs not.
#define AOV_DIRECT 0
#define AOV_ALBEDO 1
#define AOV_NORMAL 2
#define AOV_DEPTH 3
#define AOV_SHADOW 4
#define AOV_FINAL 5     // direct + indirect
#define AOV_INDIRECT 6  // indirect alone (albedo / pi * gathered irradiance)
#define AOV_LPV_SLICE 7  // debug: one slice of the accumulated light volume (raw, no albedo)
#define AOV_GV_SLICE 8   // debug: the same slice of the geometry (blocking) volume
#define AOV_CASCADE 9    // debug: shadow layer of the first shadowed light (cascade, cube face, hemisphere)
#define AOV_TRANSMITTANCE 10  // deep shadow map transmittance of the first light with one (1 = nothing translucent)
#define AOV_DSM_LISTS 11      // debug: list length per texel of the first deep shadow map (its map over the image)
#define AOV_RSM_DEPTH 12   // debug: layer --aov-layer of the RSM's depth (letterboxed square)
#define AOV_RSM_NORMAL 13  // debug: the RSM's normal, n * 0.5 + 0.5
#define AOV_RSM_FLUX 14    // debug: the RSM's flux (exposed and tone-mapped like radiance)
#define AOV_SHADOW_MAP 15  // debug: layer --aov-layer of the shadow-map array's depth
#define AOV_VELOCITY 16    // screen-space motion since the previous frame, pixels (xy: now minus then)
#define AOV_COUNT 17

#define ALPHA_OPAQUE 0
#define ALPHA_MASK 1
#define ALPHA_BLEND 2

#define NO_TEXTURE 0xFFFFFFFFu
// Slots of the material texture table (core/material_textures.glsl, SceneGpu): with a pass's own
// sampled images within lavapipe's 32 per stage (SceneGpu::checkTextureTable says why).
#define MATERIAL_TEXTURE_SLOTS 28
// A material's texture handle: slot | layer << TEXTURE_LAYER_SHIFT (each slot is a 2D array of one size).
#define TEXTURE_LAYER_SHIFT 5
#define TEXTURE_SLOT_MASK 31u
#define NO_SHADOW (-1)  // GpuLight.shadowIndex of an unshadowed light

// Per-frame constants of the camera view.
struct FrameUniforms {
    mat4 viewProj;
    mat4 invViewProj;
    mat4 previousViewProj;  // the previous frame's viewProj (velocity); this frame's on the first
    mat4 reprojection;      // previousViewProj * inverse(viewProj), in double precision: this frame's clip
                            // position -> the previous frame's, for points that did not move (exact when
                            // the camera stood still, which a float round trip through the world is not)
    vec3 eye;
    float farPlane;
    uint width;
    uint height;
    uint lightCount;
    uint aov;            // AOV_*
    uint giValid;        // 1: the indirect irradiance image is valid (GI on)
    uint visibilityIds;  // 1: visibility IDs valid (the camera's visibility path: velocity follows moving instances)
    uint probeX;         // the probed pixel (PROBE_OFF: none)
    uint probeY;
    float pixelSpread;   // world size of a pixel at unit distance (2 tan(fovy/2) / height)
    uint pad0;
    uint pad1;
    uint pad2;
};

#define PROBE_OFF 0xFFFFFFFFu

// Every AOV at one pixel (the viewer's pixel probe), written by lighting/lighting.comp for the pixel
// FrameUniforms.probeX, probeY name, as the AOV images would hold them.
struct PixelProbe {
    vec4 finalRadiance;  // rgb = direct + indirect, w = 1 on a surface, 0 on the background
    vec4 direct;         // rgb = direct radiance
    vec4 indirect;       // rgb = indirect radiance (albedo / pi * irradiance), w unused
    vec4 irradiance;     // rgb = gathered indirect irradiance (0 with --gi none)
    vec4 albedo;         // rgb = albedo
    vec4 normal;         // xyz = shading normal (hair: tangent), w = shading model (G-buffer .w)
    vec4 position;       // xyz = world position, w = distance to the eye (the depth AOV)
    vec4 shadow;         // x = first shadowed light's visibility, y = its layer code (-1: none), z = DSM transmittance
    vec4 velocity;       // xy = the velocity AOV (pixels), zw unused
};

// One light as the lighting pass sees it. Units as in scene.h: directional radiance.rgb is
// irradiance (W/m^2) facing the light, spot/point radiance.rgb is intensity (W/sr).
struct GpuLight {
    vec3 position;    // world
    uint type;        // LIGHT_*
    vec3 direction;   // the direction the light travels
    float range;      // 0 = infinite
    vec3 radiance;    // color * intensity
    int shadowIndex;  // GpuShadowLight and shadow-mask layer (NO_SHADOW = unshadowed)
    float cosInner;   // spot cone
    float cosOuter;
    // The light's first shadow layer, for passes that want one view of the light (the full layer
    // list with cascades and cube faces is the shadow-layer table, src/shadow):
    float normalOffset;     // texels
    uint perspective;       // 1: perspective, 0: orthographic
    float shadowTexelSize;  // texel world size (ortho) or per unit distance (perspective)
    uint pad0;
    uint pad1;
    uint pad2;
    mat4 shadowViewProj;
};

struct GpuMaterial {
    vec4 baseColor;  // linear RGBA factor
    uvec4 info;      // x = texture index or NO_TEXTURE, y = alpha mode, z = double sided
    vec4 params;     // x = alpha cutoff
};

// One drawn instance of a mesh (Scene::instances): the one place its transform lives. A draw covers a
// run of instances of one mesh: gl_InstanceIndex is the instance (layered passes: gl_BaseInstance +
// (gl_InstanceIndex - gl_BaseInstance) / layers); compute passes index it per triangle.
#define SCENE_INSTANCES_BINDING 15  // binding of the instance table in the scene's draw set (set 0)
struct GpuInstance {
    mat4 model;   // object -> world
    mat4 normal;  // inverse transpose of model's upper 3x3 (columns 0-2)
    mat4 toPrevious;  // world now -> world in the previous frame (previous model * inverse model): velocity
    uvec4 info;   // x = 1 when model mirrors (negative determinant: fronts flip), y = the drawn-triangle
                  // index of the mesh's first triangle (SceneGpu::drawnTriangles: visibility IDs), zw unused
};

// Push constants of the raster passes that draw the scene.
struct DrawPush {
    uint viewIndex;  // row of the views buffer (0 = camera, 1.. = shadow layers)
    uint material;
    uint pad0;
    uint triangleBase;  // the draw's first triangle within its mesh: visibility IDs are the instance's
                        // drawn-triangle base + this + gl_PrimitiveID + 1 (core/visibility.glsl)
};

// Tone-map modes: radiance is exposed and tone-mapped, colour data only sRGB-encoded, other data
// mapped linearly (value * scale + bias) so that normals and depth fit [0,1].
#define TONEMAP_ACES 0
#define TONEMAP_SRGB 1
#define TONEMAP_LINEAR 2

// lighting/debug_view.comp: mode.x = AOV_RSM_* or AOV_SHADOW_MAP, mode.y = the source's layer.
struct DebugViewPush {
    uvec4 mode;
};

struct TonemapPush {
    float scale;  // the exposure (radiance) or the linear scale
    float bias;   // TONEMAP_LINEAR: added after the scale
    uint mode;    // TONEMAP_*
    uint pad0;
};

// Reflective shadow maps (src/rsm): one RSM layer per shadow layer that has one.
struct GpuRsmLayer {
    mat4 viewProj;
    mat4 invViewProj;
    float texelSize;    // texel world size (orthographic) or per unit depth (perspective)
    uint perspective;   // 1: a perspective layer (spot, cube face), 0: orthographic
    uint light;         // the layer's light (index into the lights)
    uint cascade;       // cascade index + 1 (0: not a cascade)
    uint lastCascade;   // 1 on a light's last cascade
    float radiusScale;  // r_max scale
    uint pad0;
    uint pad1;
};

// RSM gather modes (rsm/gather.comp).
#define RSM_GATHER_FULL 0     // every full-resolution pixel, sampled pattern
#define RSM_GATHER_LOWRES 1   // one pixel per low-resolution cell, sampled pattern
#define RSM_GATHER_LIST 2     // the pixels listed by the interpolation pass, sampled pattern
#define RSM_GATHER_ALL_TEXELS 3  // every full-resolution pixel, every RSM texel (exact reference)

// How the gather tests whether a VPL sees its receiver (--rsm-visibility).
#define RSM_VISIBILITY_NONE 0    // every VPL lights every receiver it faces
#define RSM_VISIBILITY_DEPTH 1   // far samples: two points of the segment against the RSM's depth
#define RSM_VISIBILITY_VOXELS 2  // every sample: the segment marched through the occupancy volume
#define RSM_VISIBILITY_VIEWS 3   // every sample: points of the segment against the RSM's and the camera's depth

struct RsmPush {
    uint mode;                // RSM_GATHER_*
    uint sampleCount;
    uint layerCount;
    uint lowResFactor;
    uint width;               // output size (the low-resolution grid's or the full image's)
    uint height;
    uint rsmResolution;
    uint bilinearVpls;        // 1: VPLs interpolated bilinearly
    float normalThreshold;    // normal cos threshold (interpolation)
    float distanceThreshold;  // in pixel footprints (interpolation)
    float radius;             // r_max
    uint pad0;
    uint visibility;          // RSM_VISIBILITY_*
    uint visibilityRays;      // samples a pixel tests through the occupancy volume
    uint paperWeights;        // 1: the paper's single disc and xi1^2 weights (else the mixture)
    uint lanesPerReceiver;
    uint farByFlux;           // 1: the far half of the samples drawn by flux (rsm/flux_draw.comp)
    uint shiftedRadii;        // 1: radii shifted per receiver (pipelines with RSM_SHIFTED_RADII)
    uint visibilityPoints;    // points a segment is tested at (RSM_VISIBILITY_VIEWS)
    uint pad1;
};

// The flux-drawn VPLs of --rsm-far flux (rsm/flux_draw.comp), per layer a block of RSM_FLUX_BLOCK
// uvec4: the layer's total flux luminance (x, float bits); then RSM_FLUX_ENTRIES texels drawn with
// probability proportional to their flux luminance, stratified in the order of a Hilbert curve over
// the map, each as two uvec4 that share one 32-byte sector: its packed VPL (rsm/resolve.comp's
// texel) and its texel (x | y << 16, in x).
#define RSM_FLUX_ENTRIES 16384u
#define RSM_FLUX_BLOCK (2u + 2u * RSM_FLUX_ENTRIES)

// Push constants of rsm/flux_sums.comp and rsm/flux_draw.comp.
struct RsmFluxPush {
    uint rsmResolution;
    uint layerCount;
    uint curve;  // n: the Hilbert curve's side (n runs of n texels per layer)
    uint step;   // flux_sums.comp: 0 sums along the runs, 1 the runs' totals
    uint seed;   // flux_draw.comp: the draws' jitter
    uint pad0;
    uint pad1;
    uint pad2;
};

// The occupancy volume (src/voxel): one bit per voxel of a box around the scene, set where a surface
// (opaque or alpha-masked; not blended, not hair) touches the voxel. Voxel (x, y, z) is bit
// (x + dims.x (y + dims.y z)) of the bit words after this header.
// Bricks of OCCUPANCY_BRICK^3 voxels have a bit each too (after the voxels' words: dims.w is the
// first brick word), set where any of their voxels is: rays cross empty bricks in one step.
struct GpuOccupancyGrid {
    vec4 origin;  // xyz = the world position of voxel (0, 0, 0)'s lower corner, w = voxel size (m)
    uvec4 dims;   // xyz = voxels per axis (multiples of OCCUPANCY_BRICK), w = index of the first brick word
};
#define OCCUPANCY_BRICK 4
#define OCCUPANCY_GROUP 64          // voxelize.comp: threads (triangles) per workgroup
#define OCCUPANCY_SMALL_COLUMNS 16  // a triangle over more columns is cut into chunks of
#define OCCUPANCY_CHUNK_COLUMNS 256 // this many, one workgroup each (a wall covers tens of thousands)

struct OccupancyPush {
    uvec4 counts;  // x = drawn triangles, y = 1: walk the chunk list (else the triangles), z = chunk capacity
};

// render/gi_history.comp: temporal accumulation of the indirect irradiance.
struct GiHistoryPush {
    float alpha;       // weight of the new frame
    uint historyValid; // 1: the history holds the previous frame
    uint pad0;
    uint pad1;
};

// Push constants of the RSM resolve (rsm/resolve.comp): RSM texels from the shadow pass's visibility IDs.
struct RsmResolvePush {
    uint rsmResolution;
    uint idResolution;  // resolution of the ID layers (the shadow map's)
    uint pad0;
    uint pad1;
};

// Push constants of the camera's visibility resolve (lighting/visibility_resolve.comp).
struct VisibilityResolvePush {
    uvec4 size;   // xy = image size, zw unused
};

// Light propagation volumes (src/lpv). Volumes are buffers: light volume c, channel ch (R, G, B) is
// vec4 SH coefficients per cell at ((c * 3 + ch) * cells + cell); the geometry volume is one vec4
// per cell at (c * cells + cell), its cell k sitting at the light cells' corner k (half a cell off).
#define LPV_MAX_CASCADES 4
#define LPV_FACE_COLUMNS 4  // lpv/face_transmittance.comp: segments per side of a cell face

struct GpuLpvCascade {
    vec4 origin;  // xyz = world position of the grid's min corner, w = cell size
};

// A virtual point light after RSM down-sampling.
struct GpuVpl {
    vec4 position;  // xyz, w = 1 when the VPL exists
    vec4 normal;    // xyz unit normal, w = surfel area (world, on the surface)
    vec4 flux;      // rgb reflected flux, w unused
};

struct LpvPush {
    uint resolution;        // cells per axis
    uint cascadeCount;
    uint iteration;         // propagate.comp: this step (0: the first)
    uint farFromIteration;  // propagate.comp: the step from which a coarser cascade's light sums as far
    uint vplCount;
    uint rsmResolution;     // the RSM source's resolution
    uint vplResolution;     // the down-sampled resolution
    uint layerCount;
    uint occlusion;         // 1: geometry blocks the light
    float blendCells;       // gather blend band in cells
    uint cameraGeometryStep;  // G-buffer injection step (pixels)
    uint voxelFaces;        // 1: occlusion from the occupancy volume's faces, 0: from the geometry volume
    uint sliceAxis;         // gather.comp's slice views
    uint sliceIndex;
    uint pad0;
    uint pad1;
    GpuLpvCascade cascades[LPV_MAX_CASCADES];
};

// ---- Shadow maps (src/shadow, shaders/shadow) ----
// Filters (GpuShadowLight.info.w; the same values as penumbra::ShadowFilter in scene/scene.h).
#define SHADOW_FILTER_HARD 1
#define SHADOW_FILTER_PCF 2
#define SHADOW_FILTER_PCSS 3
#define SHADOW_FILTER_VSM 4
#define SHADOW_FILTER_EVSM 5
#define SHADOW_FILTER_MSM 6
// How a shadowed light's layers cover space (GpuShadowLight.info.z).
#define SHADOW_KIND_SINGLE 0      // one perspective layer (spot)
#define SHADOW_KIND_CASCADES 1    // directional: orthographic cascades, chosen by view depth
#define SHADOW_KIND_CUBE 2        // point: 6 perspective faces +x, -x, +y, -y, +z, -z
#define SHADOW_KIND_PARABOLOID 3  // point: 2 paraboloid hemispheres around +axis and -axis
// Projection of one layer (GpuShadowLayer.info.x).
#define SHADOW_PROJ_ORTHO 0
#define SHADOW_PROJ_PERSPECTIVE 1
#define SHADOW_PROJ_PARABOLOID 2
#define SHADOW_NO_MOMENTS 0xFFFFFFFFu

// One shadowed light; GpuLight.shadowIndex is its index here and its layer in the shadow mask.
struct GpuShadowLight {
    uvec4 info;    // x = first layer, y = layer count, z = SHADOW_KIND_*, w = SHADOW_FILTER_*
    vec4 params;   // x = normal offset (texels), y = PCSS penumbra scale (light diameter for spot and
                   // point lights, 2 tan(angular radius) for directional ones), zw unused
};

// One layer of the shadow-map array.
struct GpuShadowLayer {
    mat4 viewProj;  // world -> clip; paraboloid layers: world -> the hemisphere's view space
    vec4 params;    // x = texel world size (ortho) or per unit distance (perspective; paraboloid: on
                    // its axis), y = near, z = far (view distances of depth 0 and 1), w = paraboloid disc scale
    vec4 split;     // cascades: x = near, y = far split (camera view depths), zw unused
    uvec4 info;     // x = SHADOW_PROJ_*, y = moment layer or SHADOW_NO_MOMENTS, z = moment filter, w unused
};

struct GpuShadowParams {
    vec4 kernel;   // x = PCF radius (texels), y = PCSS max search radius (texels), z = cascade blend band
                   // (fraction of a cascade), w unused
    vec4 moments;  // x = light-bleeding reduction, y = EVSM positive exponent, z = negative, w = MSM bias
    uvec4 info;    // x = shadow-map resolution, y unused,
                   // z = moment blur radius (texels), w = shadowed light count
    vec4 poisson[16];  // 32 points of a progressive Poisson-disc set in the unit disc (xy, zw):
                       // any prefix is well spread, so PCF takes the first 16 and PCSS all 32
};

// Push constants of the shadow raster passes (layered: instance i draws layer firstLayer + i with
// views row viewIndex + i). Starts like DrawPush so that shared fragment code reads `material`.
struct ShadowDrawPush {
    uint viewIndex;
    uint material;
    uint firstLayer;
    uint layerCount;    // instances of a draw = scene instances x layers (layer fastest)
    uvec4 ids;          // x = the draw's first triangle within its mesh (DrawPush.triangleBase), yzw unused
    vec4 paraboloid;  // x = near, y = far, z = disc scale, w = max angle per tessellated edge (radians)
};

// ---- Hair and deep shadow maps (src/dsm, shaders/dsm) ----
// Shading model in the G-buffer normal's w: surfaces store their normal (w = 1), hair its tangent.
#define SHADING_SURFACE 1.0
#define SHADING_HAIR 2.0

#define DSM_NONE 0xFFFFFFFFu   // no node: empty list, end of a list, no neighbour link
#define DSM_MAX_LIST_CAP 128   // size of the resolve's sort array: the largest allowed --dsm-max-list
// A texel's entry in the heads buffer is DSM_HEAD_UINTS uints. The build counts its fragments per
// depth bucket (below); dsm.offsets gives the texel a run of entries for the buckets it keeps (the
// run's length in the first, its start in the second), where the build's second step stores those
// fragments' (depth, alpha) and the resolve then the sorted list (nodes and search keys at the run's
// indices); after the resolve the first holds the head of the sorted list (DSM_NONE: empty) and the
// second its length. The camera's pixels likewise get runs (dsm/oit_offsets.comp) and a header of
// OIT_HEADER_UINTS uints (oit.offsets' run, then oit.sort's kept layers: dsm/oit_sort.comp).
#define DSM_HEAD_UINTS 2
// The build counts a texel's fragments per depth bucket and keeps only the buckets up to the list
// cap's (dsm/depth_buckets.glsl). A bucket's place is DSM_CULLED or above when it is left out (or
// found no room): the build's second step adds to it and stores nothing. Buckets per DSM texel and
// per camera pixel (or fewer, where one buffer of them would not fit the device): 16 or 4 made the
// 100k-strand frame slower for the DSM on the H100 (12.40 and 12.42 ms against 12.24, session 26);
// 16 made it faster for the camera (9.41 -> 8.71 ms on an H200, session 27).
#define DSM_BUCKETS 8
#define OIT_BUCKETS 16
#define DSM_CULLED 0x80000000u
// A work-list entry of a texel that was counted but got no run (its tile found no room in the pool):
// the resolve only zeroes its counts (dsm/offsets.comp). Texel indices stay below 2^31: the maps'
// 48 bytes a texel must fit half the device's memory (DsmResources), under 1G texels on an 80 GB GPU.
#define DSM_WORK_UNLISTED 0x80000000u
#define OIT_HEADER_UINTS 4
// A camera node's z: a hair fragment's segment (the index of its first point among the hair points),
// where oit.shade reads the strand's own shadow (dsm/oit_hair_shadow.comp);
// OIT_NOT_HAIR for a mesh's fragment.
#define OIT_NOT_HAIR 0xFFFFFFFFu

// A DSM node is a uvec4 in the node pool: x = depth (float bits: distance from a spot light, depth
// along a directional light), y = the transmittance behind the node, z = the next node of the texel's
// sorted list, w = the link to the right neighbour texel's list (the node there
// with the largest depth <= this node's, or DSM_NONE); the upper neighbour's link is in a uint array.

// One point of a hair strand as the ribbon vertex shader reads it.
struct GpuHairPoint {
    vec4 position;  // xyz world, w = ribbon width (world; 0 at the zero-width copies bracketing a strand)
    vec4 tangent;   // xyz unit tangent, w = strand index (exact as a float up to 2^24)
};

// Push constants of every ribbon draw or compute raster (camera G-buffer and lists, shadow maps, DSM
// and DOM builds) and of the DSM build's mesh draws. Starts like DrawPush (views row, material) so
// that core/scene.vert reads it. ids.x = views row (the DSM layer in its builds), y = material
// (DOM build: its step, 0 first depths, 1 layers), z = the DSM build's depth-test light (DSM_NONE:
// none), the camera lists' image width, the DOM build's layer thickness (float bits), w = node
// capacity of the lists.
struct HairDrawPush {
    uvec4 ids;        // see above
    vec4 viewer;      // xyz = eye position (w = 1) or unit direction towards a directional light (w = 0)
    vec4 footprint;   // x = world size of a pixel/texel (orthographic) or per unit distance (perspective),
                      // y = perspective (1) or not (0), z = DSM resolution, w = min ribbon width in pixels
    vec4 buckets;     // the DSM build's depth buckets: x = the nearest depth of the translucent casters,
                      // y = buckets per unit of depth, z = buckets per texel (DsmPush.buckets.x),
                      // w = the build's step (0: count, 1: store)
};

// The deep shadow map of light i is entry i (lighting reads it for every light).
struct GpuDsmLight {
    mat4 viewProj;  // world -> the DSM's clip space
    vec4 viewer;    // as HairDrawPush.viewer: node depths are measured from it
    float texelSize;     // texel world size (ortho) or per unit distance (perspective)
    uint projection;     // DSM_PROJECTION_*
    int layer;           // DSM layer (< 0: the light has no DSM; a cube: its first face's)
    uint resolution;
    float filterWidth;   // PCF box width (texels)
    float depthBias;     // texels
    float normalOffset;  // texels
    uint firstFace;      // a cube's first face entry (faces +x, -x, +y, -y, +z, -z follow the lights' entries)
    uint opacityMaps;    // 1: deep opacity maps (--shadow dom; heads hold each texel's first depth, the node
                         // at the texel's index its DOM_LAYERS optical depths), 0: lists
    float layerThickness;  // deep opacity map layer thickness (world units)
    uint pad0;
    uint binarySearch;   // 1: lists looked up by binary search (--dsm-lookup search), 0: through the
                         // neighbour links (links)
};
#define DSM_PROJECTION_ORTHO 0
#define DSM_PROJECTION_PERSPECTIVE 1
#define DSM_PROJECTION_CUBE 2  // a point light's entry: its six faces' entries follow (firstFace)
#define DOM_LAYERS 4  // opacity layers of a deep opacity map texel (one vec4)

// Counters of one frame (cleared before the build; read back for the report).
struct DsmStats {
    uvec4 build;  // x = light-space fragments, y = fragments skipped by the depth test against opaque
                  // casters, z = fragments dropped for want of room in the pool (their tiles' whole),
                  // w = entries given to the texels' runs (dsm/offsets.comp)
    uvec4 lists;  // x = nodes kept, y = nodes dropped beyond the max list length, z = longest list,
                  // w = texels with a list
};

// Push constants of the resolve and link passes.
struct DsmPush {
    uvec4 sizes;    // x = resolution, y = layer count, z = node capacity, w = max list length
    uvec4 buckets;  // x = depth buckets per texel (DSM_BUCKETS or fewer), yzw unused
};

// ---- Camera translucency: hair and alphaMode BLEND surfaces (src/dsm/translucency.*) ----
// Per-pixel runs built like the DSM's (counted per depth bucket, then the kept buckets' fragments
// stored; behind-the-opaque-surface fragments rejected), then sorted, shaded and composited in compute.
#define OIT_MAX_LIST 32  // fragments composited per pixel, nearest first (the rest merged into one layer)
// A node is a uvec4: x = window depth (float bits), y = albedo r, g (half x2), z unused, w = albedo b
// and alpha (opacity x coverage; half x2; a negative alpha marks hair, shaded with Kajiya-Kay); its
// unit normal (surface) or tangent (hair), octahedral snorm16 x2, is in a uint array beside them.

struct OitStats {
    uvec4 counts;  // x = run entries given to the pixels (oit.offsets), y = kept, z = dropped beyond
                   // OIT_MAX_LIST (stored or not), w = longest list
    uvec4 cut;     // x = fragments in front of the opaque surface (all: oit.offsets), y = those in depth
                   // buckets behind the cap's (counted, never stored), z = fragments dropped for want
                   // of room in the pool (their tiles' whole), w unused
};
// A pixel's fragments beyond the cap still darken what lies behind them: the build's first step sums
// each fragment's -log(1 - alpha) per pixel in 64-bit fixed point (exact, so in any order the same).
#define OIT_LOG_SCALE 16777216.0

// Push constants of the translucency resolve.
struct OitPush {
    uvec4 sizes;  // x = width, y = height, z = node capacity, w = depth buckets per pixel
};

// ---- Compute rasterizer for depth-only views (src/raster, shaders/raster) ----
// Triangles whose pixel bounding box fits RASTER_SMALL_EXTENT on both sides are rasterized by the
// thread that set them up; larger ones are binned into RASTER_TILE_SIZE tiles, one workgroup per tile.
#define RASTER_SMALL_EXTENT 16
#define RASTER_TILE_SIZE 32
#define RASTER_SETUP_GROUP 64
#define RASTER_TILE_GROUP 256
#define RASTER_BIN_GROUP 64
#define RASTER_PLACE_GROUP 256
#define RASTER_TILE_TOUCHED 0x80000000u  // tile bin flag: a setup thread drew into the tile
// The depth buffers' clear values: 1.0 (far) in a depth layer; in each 32-bit half of an ID layer's
// depth << 32 | ID just above 1.0, so that a triangle at exactly the far plane still writes its ID
// (the hardware's test is LESS_OR_EQUAL) and the split reads an untouched texel as far and no ID.
#define RASTER_FAR_BITS 0x3F800000u
#define RASTER_ID_CLEAR_BITS 0x3F800001u
#define RASTER_SCATTER_GROUP 256
#define RASTER_NO_RECORD 0xFFFFFFFFu   // a tile entry whose triangle went the inline path (lists full)

// One triangle after setup (clipped, snapped, front-facing or double-sided, non-empty), in window
// coordinates of its layer: what coverage, depth and the alpha test need.
struct RasterTriangle {
    uvec4 xy01;      // snapped vertices 0 and 1 (int bits, subpixel units): x0, y0, x1, y1
    uvec4 xy2;       // x2, y2 (int bits), z = target layer, w = material
    vec4 origin;     // xy = float window position of vertex 0 (origin of the uv planes), z = 1: alpha-tested,
                     // w = its first tile entry (-1: the lists were full)
    vec4 depth;      // plane of z: value at pixel (0, 0) (integer pixel coordinates, as lavapipe), d/dx, d/dy;
                     // w = depth bias of the triangle
    vec4 uOverW;     // planes of u/w, v/w and 1/w (perspective-correct uv): value at origin, d/dx, d/dy
    vec4 vOverW;
    vec4 invW;
    uvec4 ids;       // x = visibility ID (drawn triangle + 1), y = ID layer + 1 (0: a depth-only layer), zw unused
};

// One layer the compute rasterizer draws (a host-written table: every layer of every light it
// draws is one row of the setup dispatch).
struct RasterLayer {
    uvec4 info;      // x = views row, y = target layer, z = 1: alphaMode BLEND casters are skipped (a deep
                     // shadow map takes them), w = ID layer + 1 (0: depth only; else depth and visibility IDs)
};

// Push constants of the compute rasterizer's passes.
struct RasterPush {
    uvec4 target;    // x = width, y = subpixel precision bits, z = triangle count, w = layer count
    uvec4 capacity;  // x = triangle records, y = tile entries, z = small-triangle extent (pixels), w = height
    vec4 bias;       // x = constant factor, y = slope factor, z = 1: fronts counter-clockwise (a y-flipped
                     // projection: the camera), w unused
};

// Counters of one frame's binning (cleared before setup).
struct RasterCounters {
    uvec4 counts;    // x = triangle records taken, y = tile entries taken, z = triangles rasterized inline
                     // because a list was full, w = tile-list entries placed (raster/place.comp)
};

#ifdef __cplusplus
// The layouts the shaders see (std430, push constants likewise): scalars pack in fours after a mat4
// or vec4, a struct rounds up to 16 bytes. tests/spirv_reflection_test.cpp compares every member
// with the compiled SPIR-V; these catch a C++-only edit at compile time.
static_assert(sizeof(GpuRsmLayer) == 160 && offsetof(GpuRsmLayer, texelSize) == 128 &&
              offsetof(GpuRsmLayer, cascade) == 140 && offsetof(GpuRsmLayer, radiusScale) == 148);
static_assert(sizeof(RsmPush) == 80 && offsetof(RsmPush, width) == 16 && offsetof(RsmPush, normalThreshold) == 32 &&
              offsetof(RsmPush, visibility) == 48 && offsetof(RsmPush, farByFlux) == 64 &&
              offsetof(RsmPush, visibilityPoints) == 72);
static_assert(sizeof(RsmFluxPush) == 32 && offsetof(RsmFluxPush, seed) == 16);
static_assert(sizeof(RsmResolvePush) == 16 && offsetof(RsmResolvePush, idResolution) == 4);
static_assert(sizeof(LpvPush) == 128 && offsetof(LpvPush, vplCount) == 16 && offsetof(LpvPush, occlusion) == 32 &&
              offsetof(LpvPush, sliceAxis) == 48 && offsetof(LpvPush, cascades) == 64);
static_assert(sizeof(TonemapPush) == 16 && offsetof(TonemapPush, mode) == 8);
static_assert(sizeof(GiHistoryPush) == 16 && offsetof(GiHistoryPush, historyValid) == 4);
static_assert(offsetof(FrameUniforms, eye) == 256 && offsetof(FrameUniforms, farPlane) == 268 &&
              offsetof(FrameUniforms, width) == 272 && offsetof(FrameUniforms, giValid) == 288 &&
              offsetof(FrameUniforms, pixelSpread) == 304);
static_assert(offsetof(GpuLight, type) == 12 && offsetof(GpuLight, direction) == 16 && offsetof(GpuLight, range) == 28 &&
              offsetof(GpuLight, radiance) == 32 && offsetof(GpuLight, shadowIndex) == 44 &&
              offsetof(GpuLight, cosInner) == 48 && offsetof(GpuLight, shadowTexelSize) == 64 &&
              offsetof(GpuLight, shadowViewProj) == 80);
static_assert(offsetof(GpuDsmLight, texelSize) == 80 && offsetof(GpuDsmLight, filterWidth) == 96 &&
              offsetof(GpuDsmLight, opacityMaps) == 112 && offsetof(GpuDsmLight, binarySearch) == 124);
static_assert(sizeof(GpuVpl) == 48 && sizeof(GpuHairPoint) == 32 && sizeof(GpuLight) == 144 &&
              sizeof(FrameUniforms) == 320 && sizeof(GpuInstance) == 208 && sizeof(DrawPush) == 16 &&
              sizeof(ShadowDrawPush) == 48 && sizeof(HairDrawPush) == 64 && sizeof(GpuShadowParams) == 304 &&
              sizeof(GpuShadowLayer) == 112 && sizeof(GpuDsmLight) == 128);
}  // namespace penumbra::gpu
#endif
#endif
