// Binding numbers of the temporal-GI passes' set 0 (temporal_gi/accumulate.comp, filter.comp), included
// by the GLSL and by src/temporal_gi: each number is written here only.
#ifndef PENUMBRA_TEMPORAL_GI_BINDINGS_H
#define PENUMBRA_TEMPORAL_GI_BINDINGS_H

// accumulate.comp
#define GI_ACCUMULATE_FRAME 0
#define GI_ACCUMULATE_CURRENT 1           // this frame's indirect irradiance
#define GI_ACCUMULATE_GBUFFER_DEPTH 2
#define GI_ACCUMULATE_GBUFFER_NORMAL 3
#define GI_ACCUMULATE_HISTORY_COLOR 4     // rgb: accumulated irradiance, a: frames it spans
#define GI_ACCUMULATE_HISTORY_MOMENTS 5   // first and second moment of the luminance
#define GI_ACCUMULATE_HISTORY_GEOMETRY 6  // x: view depth, yz: octahedral normal, w: 1 on a surface
#define GI_ACCUMULATE_OUT_COLOR 7
#define GI_ACCUMULATE_OUT_MOMENTS 8
#define GI_ACCUMULATE_OUT_GEOMETRY 9
// motion.glsl's three (visibility IDs, drawn triangles, instances) from here on.
#define GI_ACCUMULATE_MOTION_FIRST 10
#define GI_ACCUMULATE_CHANGE 13  // change_weight.comp's weights (unread when none is published)

// change_weight.comp
#define GI_CHANGE_WEIGHT_CHANGE 0  // names::kGiChange's image
#define GI_CHANGE_WEIGHT_OUTPUT 1  // r: the least weight of this frame per change texel

// filter.comp
#define GI_FILTER_FRAME 0
#define GI_FILTER_GUIDE 1     // this frame's history geometry: view depth, octahedral normal, 1 on a surface
#define GI_FILTER_INPUT 2     // the accumulation (first iteration) or the previous iteration's output
#define GI_FILTER_MOMENTS 3   // the accumulation's moments (first iteration)
#define GI_FILTER_OUTPUT 4    // rgb: filtered irradiance, a: the standard deviation of its luminance (< 0: unknown)

#endif
