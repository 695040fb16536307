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

PT_HD uint16_t halfFromFloat(float value) {
    uint32_t x = floatBits(value);
    const uint32_t sign = x & 0x80000000u;
    x ^= sign;
    uint32_t half;
    if (x > 0x7f800000u) {
        half = 0x7e00u;  // NaN stays NaN
    } else if (x >= 0x477ff000u) {
        half = 0x7bffu;  // rounds to 65504 or past it (infinity too): the largest half
    } else if (x < (113u << 23)) {
        // Below 2^-14, half's subnormals: adding 0.5 lines the mantissa up so that the float
        // addition does the rounding, to nearest even.
        const uint32_t magic = ((127u - 15u) + (23u - 10u) + 1u) << 23;
        half = floatBits(bitsFloat(x) + bitsFloat(magic)) - magic;
    } else {
        const uint32_t mantissaOdd = (x >> 13) & 1u;
        x += ((15u - 127u) << 23) + 0xfffu + mantissaOdd;  // rebias the exponent, round to even
        half = x >> 13;
    }
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
    if (exponent == 0x7c00u) return bitsFloat(sign | 0x7f800000u | bits);  // infinity, NaN
    if (exponent == 0) {  // zero and subnormals: the mantissa times 2^-24
        return bitsFloat(sign | floatBits(float(half & 0x3ffu) * 5.9604644775390625e-8f));
    }
    return bitsFloat(sign | (bits + ((127u - 15u) << 23)));
#endif
}

}  // namespace pt
