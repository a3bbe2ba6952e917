#version 460
// The analytic sky on the GPU (src/lighting/gpu_sky.h), from its Perez coefficients alone: Preetham's
// radiance (core/sky.h's AnalyticSkyModel::radiance in single precision) at the centre of every
// texel of the background and of the table Sky::analytic builds, and each table texel's share of
// the order-2 SH (its radiance times the basis integrated over the texel at Sky::sh's Gauss points),
// summed over its row. One workgroup a row, an invocation a column.
#extension GL_GOOGLE_include_directive : require
#include "sky/types.h"
#include "sky/sh_basis.glsl"

layout(local_size_x = SKY_TABLE_WIDTH) in;
layout(set = 0, binding = SKY_ANALYTIC_LAYOUT, std430) readonly buffer Layout {
    SkyLayoutRow rows[SKY_TABLE_HEIGHT];
    SkyLayoutColumn columns[SKY_TABLE_WIDTH];
};
layout(set = 0, binding = SKY_ANALYTIC_BACKGROUND, rgba16f) uniform writeonly image2D background;
layout(set = 0, binding = SKY_ANALYTIC_TABLE, rgba32f) uniform writeonly image2D table;
layout(set = 0, binding = SKY_ANALYTIC_ROW_SH, std430) writeonly buffer RowSh { vec4 rowSh[]; };
layout(push_constant) uniform Push { SkyAnalyticPush pc; };

shared vec3 partial[SKY_TABLE_WIDTH];

// The layout's direction at polar (cos, sin) and azimuth (sin, cos) (core/sky.h).
vec3 layoutDirection(vec2 polar, vec2 azimuth) { return vec3(polar.y * azimuth.x, polar.x, -polar.y * azimuth.y); }

vec3 analyticRadiance(vec3 d) {
    if (d.y <= 0.0) return vec3(0.0);
    const float cosTheta = max(d.y, 1e-3);
    const vec3 toSun = pc.toSun.xyz;
    const float cosGamma = clamp(dot(d, toSun), -1.0, 1.0);
    // The angle from the sun by its sine and cosine: acos alone loses it near the sun in single precision.
    const float gamma = atan(length(cross(d, toSun)), cosGamma);
    const vec3 yxy = pc.zenithScale.xyz * (1.0 + pc.a.xyz * exp(pc.b.xyz / cosTheta)) *
                     (1.0 + pc.c.xyz * exp(pc.d.xyz * gamma) + pc.e.xyz * cosGamma * cosGamma);
    const float luminance = yxy.x, x = yxy.y, y = yxy.z;
    const vec3 xyz = vec3(x * luminance / y, luminance, (1.0 - x - y) * luminance / y);
    // CIE XYZ to linear sRGB (Rec. 709 primaries, D65), as core/sky_analytic.cpp.
    const vec3 rgb = vec3(dot(vec3(3.2404542, -1.5371385, -0.4985314), xyz),
                          dot(vec3(-0.9692660, 1.8760108, 0.0415560), xyz),
                          dot(vec3(0.0556434, -0.2040259, 1.0572252), xyz));
    return max(rgb, vec3(0.0)) * pc.zenithScale.w;
}

void main() {
    const uint column = gl_LocalInvocationID.x, row = gl_WorkGroupID.y;
    const SkyLayoutRow r = rows[row];
    const SkyLayoutColumn c = columns[column];
    const ivec2 texel = ivec2(column, row);
    // The half float's range, as the CPU upload clamps it.
    imageStore(background, texel,
               vec4(min(analyticRadiance(layoutDirection(r.backgroundCentre, c.centre)), vec3(65000.0)), 1.0));
    const vec3 l = analyticRadiance(layoutDirection(r.tableCentre, c.centre));
    imageStore(table, texel, vec4(l, 1.0));

    float weight[9] = float[9](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    const vec2 polar[2] = vec2[2](r.gauss0, r.gauss1), azimuth[2] = vec2[2](c.gauss0, c.gauss1);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            float y[9];
            skyBasis(layoutDirection(polar[i], azimuth[j]), y);
            for (int k = 0; k < 9; ++k) weight[k] += y[k];
        }
    for (int k = 0; k < SKY_SH_COEFFICIENTS; ++k) {
        partial[column] = l * (weight[k] * r.subSolidAngle);
        barrier();
        for (uint stride = SKY_TABLE_WIDTH / 2u; stride > 0u; stride >>= 1u) {
            if (column < stride) partial[column] += partial[column + stride];
            barrier();
        }
        if (column == 0u) rowSh[row * SKY_SH_COEFFICIENTS + k] = vec4(partial[0], 0.0);
        barrier();
    }
}
