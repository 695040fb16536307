#pragma once
// Integer hashes for decorrelating sample sequences. Pure functions: the same inputs give
// the same bits on every backend.
#include <cstdint>

#include "render/math/hd.h"

namespace pt {

// Chris Wellons' "lowbias32" (hash-prospector): a good avalanche for 3 multiplies.
PT_HD uint32_t hashU32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

PT_HD uint32_t hashCombine(uint32_t seed, uint32_t v) {
    return seed ^ (hashU32(v) + 0x9e3779b9u + (seed << 6) + (seed >> 2));
}

PT_HD uint32_t reverseBits(uint32_t x) {
#if defined(__CUDA_ARCH__)
    return __brev(x);
#else
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
#endif
}

// [0, 1) from the top 24 bits, so the result is never rounded up to 1.
PT_HD float uintToUnitFloat(uint32_t x) { return float(x >> 8) * (1.0f / 16777216.0f); }

}  // namespace pt
