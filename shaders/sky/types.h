// The GPU sky's binding numbers, layout tables and push constants (sky/analytic.comp, sh_sum.comp),
// included by the GLSL and by src/lighting/gpu_sky.cpp: each number is written here only.
#ifndef PENUMBRA_SKY_TYPES_H
#define PENUMBRA_SKY_TYPES_H

#include "shared/types.h"

#ifdef __cplusplus
namespace penumbra::gpu {
#endif

// The equirectangular layout of core/sky.h at the analytic sky's size (Sky::kAnalyticWidth, Height).
#define SKY_TABLE_WIDTH 256
#define SKY_TABLE_HEIGHT 128
#define SKY_SH_COEFFICIENTS 9

// analytic.comp: one workgroup a row, an invocation a column.
#define SKY_ANALYTIC_LAYOUT 0      // SkyLayout: the texels' sample points (written once)
#define SKY_ANALYTIC_BACKGROUND 1  // rgba16f: radiance at the background's texel centres
#define SKY_ANALYTIC_TABLE 2       // rgba32f: radiance at the table's texel centres (Sky::analytic's texels)
#define SKY_ANALYTIC_ROW_SH 3      // vec4[SKY_TABLE_HEIGHT][9]: each row's share of the nine SH coefficients

// sh_sum.comp: one workgroup, an invocation a row.
#define SKY_SH_SUM_ROWS 0  // analytic.comp's row shares
#define SKY_SH_SUM_OUT 1   // vec4[9]: the sky's SH (names::kSkySh)

// Where the texels of row r are sampled (cosine and sine of the polar angle from +Y): the table's
// centre (the row's mid cosine, where Sky evaluates its table), the background's centre (the row's
// mid angle), and the two Gauss-Legendre points in cos(theta) of Sky::sh's integral, each point of
// which (with a column's two) stands for `subSolidAngle` of the sphere.
struct SkyLayoutRow {
    vec2 tableCentre;
    vec2 backgroundCentre;
    vec2 gauss0;
    vec2 gauss1;
    float subSolidAngle;
    float pad0;
    float pad1;
    float pad2;
};

// Column c's azimuth (sine, cosine) at its centre and at its two Gauss-Legendre points.
struct SkyLayoutColumn {
    vec2 centre;
    vec2 gauss0;
    vec2 gauss1;
    vec2 pad;
};

// AnalyticSkyModel (core/sky.h) in single precision: the Perez coefficients a to e of Y, x and y in
// .xyz, the zenith values over their Perez value at the zenith in .xyz with the scale to the
// renderer's radiance (the user's scale included) in .w, and the unit direction toward the sun.
struct SkyAnalyticPush {
    vec4 a;
    vec4 b;
    vec4 c;
    vec4 d;
    vec4 e;
    vec4 zenithScale;
    vec4 toSun;
};

#ifdef __cplusplus
static_assert(sizeof(SkyLayoutRow) == 48 && offsetof(SkyLayoutRow, subSolidAngle) == 32);
static_assert(sizeof(SkyLayoutColumn) == 32 && offsetof(SkyLayoutColumn, gauss1) == 16);
static_assert(sizeof(SkyAnalyticPush) == 112 && offsetof(SkyAnalyticPush, toSun) == 96);
}  // namespace penumbra::gpu
#endif
#endif
