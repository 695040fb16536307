#pragma once
// Persistent threads (Aila and Laine 2009, "Understanding the efficiency of ray traversal on
// GPUs"): a grid of only as many blocks as the GPU keeps resident, whose warps take work 32
// items at a time from a counter until none is left. With one item a thread, a block frees its
// slot on the SM only when its slowest warp is done, so the warps that drew short walks leave
// their slots idle: bench's traversal kernel kept 15.7 of the 24 warps an SM its registers
// allowed (ncu, H200, 1080p, camera rays of a 1M-triangle sphere).
//
// Not for short kernels: the wavefront's extend and shadow stages (30-300 us each) on such a
// grid, each warp claiming its every batch, made renders slower (H200, render --backend cuda
// --size 1280x720 --spp 1024, seconds: AnisotropyBarnLamp 0.684-0.690 and DepthOfFieldExample
// 0.404-0.405, where the same command had given 0.607-0.609 and 0.365-0.367 the session before).
#include <cuda_runtime.h>

#include <algorithm>
#include <cstdint>

#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/warp_atomics.cuh"
#include "render/backend/cuda/work_claims.h"

namespace pt::cuda {

// Blocks of `kernel` (launched with `blockThreads` threads) the whole GPU keeps resident at once.
inline uint32_t residentBlocks(const void* kernel, uint32_t blockThreads) {
    int device = 0, sms = 0, perSm = 0;
    PT_CUDA_CHECK(cudaGetDevice(&device));
    PT_CUDA_CHECK(cudaDeviceGetAttribute(&sms, cudaDevAttrMultiProcessorCount, device));
    PT_CUDA_CHECK(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&perSm, kernel, int(blockThreads), 0));
    return uint32_t(std::max(sms * perSm, 1));
}

// residentBlocks of kKernel, looked up once: the occupancy query walks the kernel's attributes.
template <auto kKernel, uint32_t kBlockThreads>
uint32_t residentBlocksOf() {
    static const uint32_t blocks = residentBlocks(reinterpret_cast<const void*>(kKernel), kBlockThreads);
    return blocks;
}

// Launches kKernel(args...) on a persistent grid for `count` items: no more blocks than are
// resident, nor than the items fill.
template <auto kKernel, uint32_t kBlockThreads, class... Args>
void launchPersistent(uint32_t count, cudaStream_t stream, const Args&... args) {
    const uint32_t blocks =
        std::min((count + kBlockThreads - 1) / kBlockThreads, residentBlocksOf<kKernel, kBlockThreads>());
    kKernel<<<blocks, kBlockThreads, 0, stream>>>(args...);
}

// Calls work(i) once for every i in [0, count), each warp taking 32 consecutive items at a time
// from claims->claimed. Every thread of the grid must call it (no thread may return before),
// and blocks must be whole warps.
//
// Claimed even where the grid has a thread for every item: taking the item of its index instead
// (no atomics) traced the 64-instance field's 40,177 shadow rays faster but its 53,028 diffuse
// rays slower (H200, bench at 720p, Mrays/s, two runs: 282 against 251-274, and 133 against
// 204-231). The grid was the same, and each warp took one batch either way; the cause was not
// found.
template <class Work>
__device__ __forceinline__ void forClaimedItems(WorkClaims* claims, uint32_t count, Work&& work) {
    for (;;) {
        const uint32_t i = warpReserve(&claims->claimed, true);
        if (i >= count) break;  // the counter only grows: the warp's other lanes stop at their next claim
        work(i);
    }
    __syncwarp();
    if (laneId() == 0) {
        __threadfence();  // this warp's claims happen before it counts itself done
        const uint32_t warps = gridDim.x * blockDim.x / 32u;
        if (atomicAdd(&claims->finished, 1u) == warps - 1u) {
            claims->claimed = 0;  // every other warp has finished claiming
            claims->finished = 0;
        }
    }
}

}  // namespace pt::cuda
