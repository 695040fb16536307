#pragma once
// The counters a persistent launch (persistent_grid.cuh) hands its work out with, in a header
// host code can include to allocate them.
#include <cstdint>

namespace pt::cuda {

// Both start at zero (their buffer is zeroed once when made), and a launch leaves them at zero:
// its last warp to finish resets them, so launches in a stream need no memset between them (a
// memset is a launch of its own, about 2 us on the GPU; a launch of bench's smaller ray sets
// takes 150-250 us). Launches that may run at once (other streams) need counters of their own.
struct WorkClaims {
    uint32_t claimed;   // items handed out so far
    uint32_t finished;  // warps done
};

}  // namespace pt::cuda
