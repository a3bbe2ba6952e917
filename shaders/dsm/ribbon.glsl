// A hair ribbon's cross-section at one strand point, shared by the hardware ribbons (dsm/hair.vert)
// and the compute ones (dsm/ribbon_raster.glsl): the ribbon faces the viewer (a camera or light
// position, or a directional light) and is never narrower than `minWidth` pixels/texels, so that
// it neither vanishes nor breaks up; a thinner strand passes its true coverage on as alpha (what it
// casts into a deep shadow map, what it hides in the camera). Needs `draw` (a hair push: RibbonDrawPush,
// DsmBuildPush, DomBuildPush or OitBuildPush).
#include "dsm/bindings.h"
layout(set = 0, binding = HAIR_VIEWS, std430) readonly buffer Views { mat4 viewProj[]; } views;
layout(set = 0, binding = HAIR_POINTS, std430) readonly buffer Points { GpuHairPoint points[]; };
layout(set = 0, binding = HAIR_STRANDS, std430) readonly buffer Strands { GpuStrand strands[]; };

struct RibbonSection {
    vec3 side;    // unit, across the strand, facing the viewer
    float drawn;  // the width drawn (world units); 0 at the zero-width copies that bracket a strand
    float alpha;  // opacity x coverage (width / drawn)
};

RibbonSection ribbonSection(GpuHairPoint point) {
    vec3 p = point.position, t = point.tangent;
    vec3 toViewer = draw.view.viewerIsPoint != 0u ? draw.view.viewer - p : draw.view.viewer;
    float dist = length(toViewer);
    vec3 side = cross(t, toViewer);
    float len = length(side);
    RibbonSection s;
    // Seen end-on the ribbon has no facing side: any direction across the strand will do.
    s.side = len > 1e-6 * dist ? side / len : normalize(cross(t, abs(t.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0)));
    float pixel = draw.view.pixelSize * (draw.view.perspective != 0u ? dist : 1.0);
    float width = point.width;
    s.drawn = width > 0.0 ? max(width, pixel * draw.view.minWidth) : 0.0;
    s.alpha = s.drawn > 0.0 ? strands[point.strand].opacity * width / s.drawn : 0.0;
    return s;
}
