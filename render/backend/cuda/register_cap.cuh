#pragma once
// Register caps for kernels, stated as registers a thread: __launch_bounds__ takes blocks an SM
// instead, which depends on the block size. Every NVIDIA GPU since Kepler has 64K 32-bit
// registers an SM (the H100 too), so "64 registers" with blocks of 128 threads is 8 blocks.
#include <cstdint>

namespace pt::cuda {

constexpr uint32_t kRegistersPerSm = 65536;

// The minimum blocks an SM for __launch_bounds__(blockThreads, ...) that holds each thread to
// at most `registers`.
constexpr uint32_t blocksPerSmFor(uint32_t blockThreads, uint32_t registers) {
    return kRegistersPerSm / (blockThreads * registers);
}

}  // namespace pt::cuda
