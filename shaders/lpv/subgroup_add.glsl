// Atomic adds of 4 coefficients where many invocations of a subgroup hit the same cell (injection
// into coarse cells): each round takes the cell of the first pending invocation, the invocations
// with that cell sum their coefficients in the subgroup and one of them adds the sum. A subgroup of
// neighbouring RSM texels covers a few coarse cells, so a few rounds take them all (with only the
// all-in-one-cell case summed, cornell's injection cost 3x its one-grid cost on the H100). Rounds
// stop when a cell has a single invocation (fine cells: each adds its own, all in parallel) or after
// LPV_ADD_ROUNDS. Needs GL_KHR_shader_subgroup_basic, _ballot and _arithmetic and
// GL_EXT_shader_atomic_float. A macro: GLSL functions cannot take a buffer's array.
#define LPV_ADD_ROUNDS 8u
#define ADD_COEFFS(volume, base, coeffs)                                                   \
    {                                                                                      \
        bool pending_ = true;                                                              \
        for (uint round_ = 0u; pending_ && round_ < LPV_ADD_ROUNDS; ++round_) {            \
            const uint cell_ = subgroupBroadcastFirst(base);                               \
            if (subgroupBallotBitCount(subgroupBallot(base == cell_)) < 2u) break;         \
            if (base == cell_) {                                                           \
                const vec4 sum_ = subgroupAdd(coeffs);                                     \
                if (subgroupElect())                                                       \
                    for (uint j = 0; j < 4u; ++j) atomicAdd(volume[cell_ + j], sum_[j]);   \
                pending_ = false;                                                          \
            }                                                                              \
        }                                                                                  \
        if (pending_)                                                                      \
            for (uint j = 0; j < 4u; ++j) atomicAdd(volume[base + j], coeffs[j]);          \
    }
