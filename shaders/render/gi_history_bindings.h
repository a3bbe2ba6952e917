// Binding numbers of the temporal GI pass's set 0 (render/gi_history.comp), included by the GLSL
// and by src/render/gi_history.cpp: each number is written here only.
#ifndef PENUMBRA_GI_HISTORY_BINDINGS_H
#define PENUMBRA_GI_HISTORY_BINDINGS_H

#define GI_HISTORY_FRAME 0
#define GI_HISTORY_CURRENT 1
#define GI_HISTORY_GBUFFER_DEPTH 2
#define GI_HISTORY_HISTORY 3
#define GI_HISTORY_HISTORY_DEPTH 4
#define GI_HISTORY_OUT 5
#define GI_HISTORY_OUT_DEPTH 6
// render/motion.glsl's three (visibility IDs, drawn triangles, instances) from here on.
#define GI_HISTORY_MOTION_FIRST 7

#endif
