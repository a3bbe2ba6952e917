// Atomic adds of fixed-point coefficients (lpv/fixed_point.glsl), a subgroup's invocations of one
// cell summed first (lpv/subgroup_cells.glsl, included before this). Needs GL_EXT_shader_atomic_int64.
// A subgroup's sum of 64-bit integers, exact: three 21-bit limbs summed as 32-bit integers (a subgroup
// of up to 2^10 invocations cannot overflow them), put together in wrapping 64-bit arithmetic, which
// is exact wherever the true sum fits.
i64vec4 subgroupAddExact(i64vec4 v) {
    const int64_t mask = 0x1FFFFFl;
    const ivec4 lo = subgroupAdd(ivec4(v & mask)), mid = subgroupAdd(ivec4((v >> 21) & mask));
    const ivec4 hi = subgroupAdd(ivec4(v >> 42));
    return (i64vec4(hi) << 42) + (i64vec4(mid) << 21) + i64vec4(lo);
}

// Adds the fixed-point coefficients `q` (i64vec4, lpv/fixed_point.glsl) to volume[base .. base + 3].
#define ADD_FIXED(volume, base, q)                                                           \
    LPV_BY_CELL(base,                                                                        \
                const i64vec4 sum_ = subgroupAddExact(q);                                    \
                if (subgroupElect()) for (uint j = 0u; j < 4u; ++j) atomicAdd(volume[cell_ + j], sum_[j]);, \
                for (uint j = 0u; j < 4u; ++j) atomicAdd(volume[base + j], q[j]);)
