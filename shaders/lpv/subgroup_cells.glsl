// Atomics where many invocations of a subgroup hit the same cell (injection into coarse cells): each
// round takes the cell (`key`) of the first pending invocation, the invocations with that cell
// combine their values in the subgroup (GROUPED, which may name the round's cell `cell_`) and one of
// them does the atomics. A subgroup of neighbouring RSM texels covers a few coarse cells, so a few
// rounds take them all (combining only the all-in-one-cell case left most atomics
// uncombined). Rounds stop when a cell has a single invocation (fine cells: each does
// its own, ALONE, all in parallel) or after LPV_SUBGROUP_ROUNDS. Needs GL_KHR_shader_subgroup_basic,
// _ballot and _arithmetic. Macros: GLSL functions cannot take a buffer's array.
#define LPV_SUBGROUP_ROUNDS 8u
#define LPV_BY_CELL(key, GROUPED, ALONE)                                                   \
    {                                                                                      \
        bool pending_ = true;                                                              \
        for (uint round_ = 0u; pending_ && round_ < LPV_SUBGROUP_ROUNDS; ++round_) {       \
            const uint cell_ = subgroupBroadcastFirst(key);                                \
            if (subgroupBallotBitCount(subgroupBallot(key == cell_)) < 2u) break;          \
            if (key == cell_) {                                                            \
                GROUPED                                                                    \
                pending_ = false;                                                          \
            }                                                                              \
        }                                                                                  \
        if (pending_) {                                                                    \
            ALONE                                                                          \
        }                                                                                  \
    }
