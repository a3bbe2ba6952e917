// Atomic adds of 4 coefficients where many invocations of a subgroup hit the same cell (injection
// into coarse cells): the subgroup sums them first and one invocation adds the sum. Needs
// GL_KHR_shader_subgroup_basic, _vote and _arithmetic and GL_EXT_shader_atomic_float. A macro: GLSL
// functions cannot take a buffer's array.
#define ADD_COEFFS(volume, base, coeffs)                                              \
    if (subgroupAllEqual(base)) {                                                     \
        vec4 sum = subgroupAdd(coeffs);                                               \
        if (subgroupElect())                                                          \
            for (uint j = 0; j < 4u; ++j) atomicAdd(volume[base + j], sum[j]);        \
    } else {                                                                          \
        for (uint j = 0; j < 4u; ++j) atomicAdd(volume[base + j], coeffs[j]);         \
    }
