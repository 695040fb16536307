#pragma once
// IEEE 754 binary16 ("half") in per-pixel code that both backends run, bit-identically.
// Encoding is integer and exact float arithmetic on both (not CUDA's intrinsic, whose overflow
// goes to infinity); it rounds to nearest even (F. Giesen, "float->half variants", 2016,
// float_to_half_fast3_rtne) and saturates at +-65504, the largest half, instead of
// overflowing. Decoding is exact, so the GPU may use its conversion instruction.
#include <cstdint>

#include "render/math/hd.h"
#include "render/math/vec.h"  // floatAsInt, intAsFloat

namespace pt {

PT_HD uint32_t floatBits(float f) { return uint32_t(floatAsInt(f)); }
PT_HD float bitsFloat(uint32_t u) { return intAsFloat(int32_t(u)); }

constexpr float kHalfMax = 65504.0f;

// Branch-free (each case computed, one selected), so that the CPU converts a row of pixels as
// SIMD vectors; the cases and their order are Giesen's.
PT_HD uint16_t halfFromFloat(float value) {
    uint32_t x = floatBits(value);
    const uint32_t sign = x & 0x80000000u;
    x ^= sign;
    // Below 2^-14, half's subnormals: adding 0.5 lines the mantissa up so that the float
    // addition does the rounding, to nearest even.
    const uint32_t magic = ((127u - 15u) + (23u - 10u) + 1u) << 23;
    const uint32_t subnormal = floatBits(bitsFloat(x) + bitsFloat(magic)) - magic;
    // Rebias the exponent, round to nearest even.
    const uint32_t normal = (x + ((15u - 127u) << 23) + 0xfffu + ((x >> 13) & 1u)) >> 13;
    uint32_t half = x < (113u << 23) ? subnormal : normal;
    half = x >= 0x477ff000u ? 0x7bffu : half;  // rounds to 65504 or past it (infinity too): the largest half
    half = x > 0x7f800000u ? 0x7e00u : half;   // NaN stays NaN
    return uint16_t(half | (sign >> 16));
}

// Exact: every half is a float (so the GPU's conversion instruction gives the same float).
PT_HD float floatFromHalf(uint16_t half) {
#if defined(__CUDA_ARCH__)
    float f;
    asm("cvt.f32.f16 %0, %1;" : "=f"(f) : "h"(half));
    return f;
#else
    const uint32_t sign = uint32_t(half & 0x8000u) << 16;
    const uint32_t exponent = half & 0x7c00u, bits = uint32_t(half & 0x7fffu) << 13;
    const uint32_t special = sign | 0x7f800000u | bits;  // infinity, NaN
    // Zero and subnormals: the mantissa times 2^-24.
    const uint32_t small = sign | floatBits(float(half & 0x3ffu) * 5.9604644775390625e-8f);
    const uint32_t normal = sign | (bits + ((127u - 15u) << 23));
    return bitsFloat(exponent == 0x7c00u ? special : (exponent == 0 ? small : normal));
#endif
}

}  // namespace pt
