// Light-propagation-volume settings (defaults from TECHNIQUES.md section 4 and the seed).
#pragma once
#include <cstdint>

namespace penumbra {

// What blocks light between cells: the geometry volume (L1 lobes of the RSM's and the camera's
// surfels, Kaplanyan & Dachsbacher 2010), or the share of each cell face that the occupancy volume's
// voxels leave open (lpv/face_transmittance.comp).
enum class LpvGeometry { Surfels, Voxels };

struct LpvSettings {
    uint32_t resolution = 16;       // cells per side of each cascade (docs/techniques/lpv.md: 16 beat 24 and 32 on the GI suite)
    uint32_t iterations = 8;        // propagation steps
    uint32_t cascades = 0;          // 1..4; 0 = automatic (3)
    uint32_t rsmResolution = 2048;  // RSM rendered for injection, per light
    uint32_t vplResolution = 512;   // RSM down-sampled to this many VPLs per side
    bool occlusion = true;          // geometry volume blocks propagation (after the first step)
    // `--lpv-geometry`: voxels beat surfels on every GI-suite view (docs/techniques/lpv.md).
    LpvGeometry geometry = LpvGeometry::Voxels;
    bool cameraGeometry = true;     // also inject occluders seen by the camera (G-buffer; surfels)
    uint32_t cameraGeometryStep = 4;  // one camera surfel per step x step pixels
    float blendCells = 2.0f;        // cascade border blend band, in cells
    // The temporal gradients' reading (core/names.h GiChange): a relative change of c in a frame weighs
    // the new frame of the GI history at least c / lagTolerance. The volume holds no sampling noise, so
    // its gradients are the light's change alone and can be taken nearly whole (docs/motion.md).
    float lagTolerance = 0.1f;
    uint32_t sliceAxis = 2;         // debug AOVs lpv-slice / gv-slice: axis (0 x, 1 y, 2 z)
    uint32_t sliceIndex = 8;        // and cell index along it
};

}  // namespace penumbra
