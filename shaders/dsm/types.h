// Hair, deep shadow maps and camera translucency (src/dsm): the structs and constants its passes
// share between C++ and GLSL, laid out by the rules of shared/types.h, which includes this file (its
// includers see them all).
#ifndef PENUMBRA_DSM_TYPES_H
#define PENUMBRA_DSM_TYPES_H

#include "shared/types.h"

#ifdef __cplusplus
namespace penumbra::gpu {
#endif

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
// per camera pixel (or fewer, where one buffer of them would not fit the device): the counts whose
// 100k-strand frames measured fastest (more or fewer DSM buckets were slower; more camera ones faster).
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
    vec3 position;  // world
    float width;    // ribbon width (world; 0 at the zero-width copies bracketing a strand)
    vec3 tangent;   // unit
    uint strand;    // strand index (the strands buffer's row)
};

// One hair strand's shading (the strands buffer's row).
struct GpuStrand {
    vec3 color;     // linear albedo
    float opacity;  // the light it stops where it covers a whole texel (ribbon.glsl scales it by the width drawn)
};

// Who a hair ribbon faces and how large a pixel or texel is there (dsm/ribbon.glsl).
struct GpuRibbonView {
    vec3 viewer;          // the eye or light position, or the unit direction towards a directional light
    uint viewerIsPoint;   // 1: viewer is a position, 0: a direction
    float pixelSize;      // world size of a pixel/texel (orthographic) or per unit distance (perspective)
    uint perspective;     // 1: pixelSize is per unit distance from the viewer
    float minWidth;       // the narrowest ribbon drawn, in pixels/texels
    uint pad0;
};

// The translucent casters' depth buckets (dsm/depth_buckets.glsl) and the build's step.
struct GpuDepthBuckets {
    float nearest;   // the casters' nearest depth
    float perDepth;  // buckets per unit of depth
    uint perCell;    // buckets per texel or pixel
    uint store;      // the build's step: 0 counts the fragments, 1 stores the kept buckets'
};

// Push constants of the ribbon draws that only draw (camera G-buffer, shadow maps: dsm/hair.vert).
// Every hair push starts with the views row and has its ribbon view at offset 16, where dsm/hair.vert
// and dsm/ribbon_raster.glsl read them; the DSM's and the camera's mesh draws (core/scene.vert) read
// the material at offset 4, as DrawPush's.
struct RibbonDrawPush {
    uint viewRow;
    uint pad0;
    uint pad1;
    uint pad2;
    GpuRibbonView view;
};

// The deep shadow map's build (dsm/build_hair.*, dsm/build_mesh.frag: dsm/dsm_insert.glsl).
struct DsmBuildPush {
    uint viewRow;         // the DSM layer (its views row)
    uint material;        // a mesh draw's material
    uint depthTestLight;  // the scene light whose opaque shadow map hides fragments (DSM_NONE: no test)
    uint resolution;      // the DSM's
    GpuRibbonView view;
    GpuDepthBuckets buckets;
};

// The deep opacity map's build (dsm/opacity_build.comp).
struct DomBuildPush {
    uint viewRow;          // the DSM layer (its views row)
    uint layers;           // 0: the first depths, 1: the layers behind them
    float layerThickness;  // world units
    uint resolution;       // the map's
    GpuRibbonView view;
};

// The camera translucency build (dsm/oit_hair.*, dsm/oit_mesh.frag: dsm/oit_insert.glsl).
struct OitBuildPush {
    uint viewRow;   // 0: the camera
    uint material;  // a mesh draw's material
    uint width;     // the image's width
    uint pad0;
    GpuRibbonView view;
    GpuDepthBuckets buckets;
};

// The deep shadow map of light i is entry i (lighting reads it for every light).
struct GpuDsmLight {
    mat4 viewProj;  // world -> the DSM's clip space
    vec3 viewer;    // as GpuRibbonView.viewer: node depths are measured from it
    uint viewerIsPoint;  // 1: viewer is the light's position, 0: the direction towards it
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
    uint fragments;      // light-space fragments
    uint hidden;         // fragments skipped by the depth test against opaque casters
    uint overflow;       // fragments dropped for want of room in the pool (their tiles' whole)
    uint runEntries;     // entries given to the texels' runs (dsm/offsets.comp)
    uint kept;           // nodes kept
    uint beyondMaxList;  // nodes dropped beyond the max list length
    uint longest;        // the longest list
    uint lists;          // texels with a list
};

// Push constants of the resolve and link passes.
struct DsmPush {
    uint resolution;
    uint layerCount;
    uint nodeCapacity;
    uint maxList;          // max list length
    uint bucketsPerTexel;  // depth buckets per texel (DSM_BUCKETS or fewer)
    uint pad0;
    uint pad1;
    uint pad2;
};

// ---- Camera translucency: hair and alphaMode BLEND surfaces (src/dsm/translucency.*) ----
// Per-pixel runs built like the DSM's (counted per depth bucket, then the kept buckets' fragments
// stored; behind-the-opaque-surface fragments rejected), then sorted, shaded and composited in compute.
#define OIT_MAX_LIST 32  // fragments composited per pixel, nearest first (the rest merged into one layer)
// A node is a uvec4: x = window depth (float bits), y = albedo r, g (half x2), z unused, w = albedo b
// and alpha (opacity x coverage; half x2; a negative alpha marks hair, shaded with Kajiya-Kay); its
// unit normal (surface) or tangent (hair), octahedral snorm16 x2, is in a uint array beside them.

struct OitStats {
    uint runEntries;     // run entries given to the pixels (oit.offsets)
    uint kept;
    uint beyondMaxList;  // dropped beyond OIT_MAX_LIST (stored or not)
    uint longest;        // the longest list
    uint fragments;      // fragments in front of the opaque surface (all: oit.offsets)
    uint leftOut;        // of those, in depth buckets behind the cap's (counted, never stored)
    uint overflow;       // fragments dropped for want of room in the pool (their tiles' whole)
    uint pad0;
};
// A pixel's fragments beyond the cap still darken what lies behind them: the build's first step sums
// each fragment's -log(1 - alpha) per pixel in 64-bit fixed point (exact, so in any order the same).
#define OIT_LOG_SCALE 16777216.0

// Push constants of the translucency resolve.
struct OitPush {
    uint width;
    uint height;
    uint nodeCapacity;
    uint bucketsPerPixel;  // depth buckets per pixel
};

#ifdef __cplusplus
static_assert(offsetof(GpuDsmLight, texelSize) == 80 && offsetof(GpuDsmLight, filterWidth) == 96 &&
              offsetof(GpuDsmLight, opacityMaps) == 112 && offsetof(GpuDsmLight, binarySearch) == 124);
static_assert(sizeof(GpuHairPoint) == 32 && sizeof(GpuDsmLight) == 128);
static_assert(sizeof(GpuStrand) == 16 && offsetof(GpuStrand, color) == 0 && offsetof(GpuStrand, opacity) == 12);
static_assert(sizeof(GpuRibbonView) == 32 && sizeof(GpuDepthBuckets) == 16 && offsetof(GpuRibbonView, pixelSize) == 16);
static_assert(sizeof(RibbonDrawPush) == 48 && offsetof(RibbonDrawPush, view) == 16);
static_assert(sizeof(DsmBuildPush) == 64 && offsetof(DsmBuildPush, material) == 4 && offsetof(DsmBuildPush, view) == 16 &&
              offsetof(DsmBuildPush, buckets) == 48);
static_assert(sizeof(DomBuildPush) == 48 && offsetof(DomBuildPush, view) == 16);
static_assert(sizeof(OitBuildPush) == 64 && offsetof(OitBuildPush, material) == 4 && offsetof(OitBuildPush, view) == 16 &&
              offsetof(OitBuildPush, buckets) == 48);
static_assert(offsetof(GpuDsmLight, viewer) == 64 && offsetof(GpuDsmLight, viewerIsPoint) == 76);
static_assert(sizeof(DsmStats) == 32 && sizeof(DsmPush) == 32 && sizeof(OitStats) == 32 && sizeof(OitPush) == 16);
}  // namespace penumbra::gpu
#endif
#endif
