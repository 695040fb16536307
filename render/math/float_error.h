#pragma once
// Bounds on float rounding error, for code that must stay on the right side of a surface.
// With round-to-nearest, a float operation on exact operands is off by at most u = 2^-24 of its
// result; a value computed through n such roundings is within gamma(n) = n u / (1 - n u) of its
// exact value, relative to the sum of the magnitudes of its terms (Higham, "Accuracy and
// Stability of Numerical Algorithms", 2002, ch. 3; pbrt-v4 section 6.8.1). Both backends round
// alike (no contraction into FMA: -ffp-contract=off on the host, -fmad=false on the device).
#include "render/math/vec.h"

namespace pt {

constexpr float kUnitRoundoff = 0x1p-24f;

PT_HD constexpr float gammaBound(int n) {
    return (float(n) * kUnitRoundoff) / (1.0f - float(n) * kUnitRoundoff);
}

// The neighbouring float towards +infinity, and towards -infinity (finite inputs; zero steps to
// the smallest denormal of the right sign).
PT_HD float nextFloatUp(float v) {
    if (v == 0.0f) return intAsFloat(1);
    const int32_t bits = floatAsInt(v);
    return intAsFloat(v > 0.0f ? bits + 1 : bits - 1);
}
PT_HD float nextFloatDown(float v) {
    if (v == 0.0f) return -intAsFloat(1);
    const int32_t bits = floatAsInt(v);
    return intAsFloat(v > 0.0f ? bits - 1 : bits + 1);
}

}  // namespace pt
