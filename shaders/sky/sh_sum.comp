#version 460
// The analytic sky's order-2 SH (names::kSkySh): analytic.comp's row shares summed, a tree over
// the rows for each coefficient. One workgroup, an invocation a row.
#extension GL_GOOGLE_include_directive : require
#include "sky/types.h"

layout(local_size_x = SKY_TABLE_HEIGHT) in;
layout(set = 0, binding = SKY_SH_SUM_ROWS, std430) readonly buffer RowSh { vec4 rowSh[]; };
layout(set = 0, binding = SKY_SH_SUM_OUT, std430) writeonly buffer Sh { vec4 coefficients[SKY_SH_COEFFICIENTS]; };

shared vec3 partial[SKY_TABLE_HEIGHT];

void main() {
    const uint row = gl_LocalInvocationID.x;
    for (int k = 0; k < SKY_SH_COEFFICIENTS; ++k) {
        partial[row] = rowSh[row * SKY_SH_COEFFICIENTS + k].rgb;
        barrier();
        for (uint stride = SKY_TABLE_HEIGHT / 2u; stride > 0u; stride >>= 1u) {
            if (row < stride) partial[row] += partial[row + stride];
            barrier();
        }
        if (row == 0u) coefficients[k] = vec4(partial[0], 0.0);
        barrier();
    }
}
