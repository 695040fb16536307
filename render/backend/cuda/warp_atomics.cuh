#pragma once
// Warp-aggregated atomics: one atomic per warp instead of one per thread, for the counters and
// queues every path touches (a million threads hammering one address serialise on it).
#include <cuda_runtime.h>

#include <cstdint>

namespace pt::cuda {

__device__ __forceinline__ uint32_t laneId() { return threadIdx.x & 31u; }

// Adds each active lane's `value` to *counter with one atomic per warp.
__device__ __forceinline__ void warpAtomicAdd(unsigned long long* counter, uint32_t value) {
    const unsigned mask = __activemask();
    const uint32_t total = __reduce_add_sync(mask, value);
    if (laneId() == uint32_t(__ffs(mask) - 1) && total != 0) atomicAdd(counter, (unsigned long long)total);
}

__device__ __forceinline__ void warpAtomicAdd(uint32_t* counter, uint32_t value) {
    const unsigned mask = __activemask();
    const uint32_t total = __reduce_add_sync(mask, value);
    if (laneId() == uint32_t(__ffs(mask) - 1) && total != 0) atomicAdd(counter, total);
}

// Reserves one slot of a counted array (count at *size) for every active lane whose `take` is
// true, with one atomic per warp; the lanes of a warp get consecutive slots. Returns this lane's
// slot (meaningless where `take` is false).
__device__ __forceinline__ uint32_t warpReserve(uint32_t* size, bool take) {
    const unsigned mask = __activemask();
    const unsigned ballot = __ballot_sync(mask, take);
    if (ballot == 0) return 0;
    const uint32_t leader = uint32_t(__ffs(mask) - 1);
    uint32_t base = 0;
    if (laneId() == leader) base = atomicAdd(size, uint32_t(__popc(ballot)));
    base = __shfl_sync(mask, base, int(leader));
    return base + uint32_t(__popc(ballot & ((1u << laneId()) - 1u)));
}

// Appends `value` to queue (count at *size) for every active lane whose `push` is true; the
// lanes of a warp land in consecutive slots.
__device__ __forceinline__ void warpAppend(uint32_t* queue, uint32_t* size, uint32_t value, bool push) {
    const uint32_t slot = warpReserve(size, push);
    if (push) queue[slot] = value;
}

}  // namespace pt::cuda
