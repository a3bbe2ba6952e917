#version 460
// Deep opacity map build (Yuksel & Keyser 2008; --shadow dom), hair in compute through the ribbon
// walk (dsm/ribbon_raster.glsl), two dispatches per map:
//   ids.y = 0: each texel's first depth, the nearest strand fragment (atomicMin of an order-keeping
//              uint, so that negative depths along a directional light sort too);
//   ids.y = 1: every fragment adds its optical depth -ln(1 - alpha) to the layer it falls in: layer
//              k covers [first + k L, first + (k + 1) L) (L = uintBitsToFloat(ids.z)), the last one
//              everything behind. Sums of optical depth, not of alpha: the product of the fragments'
//              (1 - alpha) is then exact within a texel, whatever the order.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require
#include "shared/types.h"
#include "dsm/dsm_common.glsl"

layout(local_size_x = 64) in;
layout(push_constant) uniform Push { DomBuildPush draw; };

#include "dsm/ribbon.glsl"
layout(set = 0, binding = DOM_BUILD_FIRST_DEPTHS, std430) buffer Heads { uint firstDepth[]; };
layout(set = 0, binding = DOM_BUILD_LAYERS, std430) buffer Layers { float opticalDepth[]; };  // DOM_LAYERS per texel
#include "dsm/ribbon_raster.glsl"

void ribbonFragment(ivec2 pixel, float ndcDepth, float viewerDepth, float alpha, vec3 world, vec3 tangent,
                    vec3 colour, uint segment) {
    if (alpha <= 0.0) return;
    uint res = draw.resolution;
    uint texel = (draw.viewRow * res + uint(pixel.y)) * res + uint(pixel.x);
    if (draw.layers == 0u) {
        atomicMin(firstDepth[texel], orderedDepth(viewerDepth));
        return;
    }
    float layer = (viewerDepth - fromOrderedDepth(firstDepth[texel])) / draw.layerThickness;
    uint k = uint(clamp(layer, 0.0, float(DOM_LAYERS - 1)));
    atomicAdd(opticalDepth[texel * DOM_LAYERS + k], -log(max(1.0 - alpha, 1e-6)));
}

void main() {
    uint i;
    if (ribbonSegmentIndex(i)) rasterRibbonSegment(i, vec2(float(draw.resolution)));
}
