// Luminance of linear Rec.709 RGB (the weights of the sRGB primaries).
#ifndef PENUMBRA_LUMINANCE_GLSL
#define PENUMBRA_LUMINANCE_GLSL
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
#endif
