// Reflective-shadow-map settings (defaults from Dachsbacher & Stamminger 2005 and the seed).
#pragma once
#include <cstdint>

namespace penumbra {

enum class RsmMode {
    Interpolated,  // low-resolution gather + the paper's interpolation, full gather where it fails
    Full,          // sampled gather at every full-resolution pixel
    AllTexels,     // every RSM texel at every pixel: the exact sum (tests, small RSMs only)
};

// How a sample at radius xi1 * r_max is weighted. Uniform (xi1, xi2) in polar form puts a sample
// density proportional to 1/r on the disc, so the unbiased weight is proportional to xi1; the
// paper (and the seed) use xi1^2, which further favours far samples. Both are normalised so that a
// uniform VPL field gives the exact disc sum.
enum class RsmWeights { Unbiased, Paper };

// Whether a VPL sees its receiver. Without it light reaches receivers through walls, floors and
// curtains, and scenes of rooms (Sponza, VC) get far too bright a bounce (docs/techniques/rsm.md).
enum class RsmVisibility {
    None,    // every VPL lights every receiver it faces
    Depth,   // samples beyond r_max: two points of the segment tested against the RSM's depth
    Voxels,  // every sample: the segment marched through the scene's occupancy volume (src/voxel)
    Views,   // every sample: points of the segment solid where both the light's and the camera's depth hide them
};

// The pattern's radii: the same for every receiver (the seed's way), or shifted per receiver (xi1 +
// a hash of its position, modulo 1). With the far disc, fixed radii are a fixed quadrature of the
// near field that leaves it dark, and shifting needs the per-sample weights of a heavier pipeline.
// With flux draws the gather weighs every sample in the shader anyway, so shifting is nearly free
// and makes neighbouring receivers' estimates independent, which the interpolation's filter then
// averages (docs/techniques/rsm.md). Voxel visibility always shifts.
enum class RsmRadii { Fixed, Shifted };

// Where the unbiased pattern's far half of the samples goes: a polar disc over the whole map (dense
// near the receiver, blind to where the light is), or texels drawn by their flux luminance
// (rsm/flux_draw.comp), combined with the r_max disc by the balance heuristic (rsm/gather.glsl).
enum class RsmFar { Disc, Flux };

inline constexpr uint32_t kMaxRsmSamples = 16384;  // --rsm-samples' range: the pattern buffer's size

struct RsmSettings {
    uint32_t resolution = 512;   // RSM texels per side (per shadowed light)
    // Gather samples per receiver. 300 with views visibility (3 points a sample): as accurate on the GI
    // suite as 350 within its references' noise, for a cheaper gather (docs/techniques/rsm.md).
    uint32_t samples = 300;
    // Samples per receiver in a frame that adds to a GI history (src/temporal_gi): the history averages
    // a new pattern each frame, so each frame needs only a share of the estimate (at most `samples`).
    // A frame that starts a history (the first, a cut, a light's jump) takes `samples`.
    uint32_t frameSamples = 64;
    // The temporal gradients' reading (core/names.h GiChange): a relative change of c in a frame, beyond
    // what the gradients' spread explains, weighs the new frame at least c / lagTolerance. A moving light
    // re-samples the RSM, so the gradients also hold sampling changes; at 3 a fast sun over Sponza
    // flickers within 1.5x of the path tracer (docs/motion.md). Lower: less lag, more flicker.
    float lagTolerance = 3.0f;
    float radius = 0.25f;        // r_max in RSM uv units
    uint32_t seed = 1;           // the sample pattern is generated once from it (reproducible)
    RsmMode mode = RsmMode::Interpolated;
    RsmWeights weights = RsmWeights::Unbiased;
    uint32_t lowResFactor = 4;   // low-resolution gather: one sample per factor x factor pixels
    float normalThreshold = 0.9f;    // interpolation: min |cos| between the pixel's and a sample's normal
    // A sun's RSM from its widest cascade only (default), or one per cascade with the seed's choice of
    // cascade per receiver and r_max kept at the finest cascade's world size. Per-cascade RSMs miss most
    // of the path-traced bounce on large scenes: a fine cascade does not hold the distant VPLs that
    // light its receivers (docs/techniques/rsm.md).
    bool perCascade = false;
    float distanceThreshold = 1.0f;  // interpolation: max distance off the tangent plane, in low-res cell footprints
    // A sample reads the VPL of the texel it falls in (nearest), or the four around it weighted
    // bilinearly: 4x the VPL evaluations, but a sample's light moves continuously as the light's
    // texel lattice moves under it (moving lights; docs/techniques/rsm.md).
    bool bilinearVpls = false;
    // Voxels removes most of the light through walls but marches every ray through a volume, several
    // times the cost of the whole gather, and its ratio's noise adds error on small rooms: an expert's
    // choice. Views (the default) removes about half of the excess light on walled scenes and makes no
    // scene of the GI suite worse, for a fraction of the gather's cost (docs/techniques/rsm.md).
    RsmVisibility visibility = RsmVisibility::Views;
    RsmRadii radii = RsmRadii::Shifted;
    RsmFar far = RsmFar::Flux;
    uint32_t voxelResolution = 128;  // occupancy volume: voxels along the scene's longest side
    // Voxels: of a pixel's samples, this many (evenly strided) walk the occupancy volume; the
    // visible share of their light scales the light of all (a ratio estimate of the visibility).
    uint32_t visibilityRays = 16;
    // Views: points a VPL-receiver segment is tested at (rsm/gather.glsl, segmentVisibility). Each point
    // costs a fixed share of the gather; 3 is where a further point stopped paying for itself on the
    // GI suite (docs/techniques/rsm.md).
    uint32_t visibilityPoints = 3;
};

}  // namespace penumbra
