// Binding numbers of the camera's visibility resolve (lighting/visibility_resolve.comp), included by
// the GLSL and by src/lighting/gbuffer_pass.cpp; bindings 0-2 are the scene's resolve set
// (SceneGpu::resolveSetBindings), 4 is free.
#ifndef PENUMBRA_GBUFFER_BINDINGS_H
#define PENUMBRA_GBUFFER_BINDINGS_H

#define VISIBILITY_RESOLVE_FRAME 3
#define VISIBILITY_RESOLVE_IDS 5
#define VISIBILITY_RESOLVE_ALBEDO 6
#define VISIBILITY_RESOLVE_NORMAL 7

#endif
