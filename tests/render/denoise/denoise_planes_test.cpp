// The denoiser's packed samples: halves rounded as IEEE 754 says, saturating instead of
// overflowing, and a filter's result that gives back what packing took off.
#include "render/denoise/denoise_planes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pt {
namespace {

TEST(HalfFloat, EveryHalfSurvivesTheRoundTrip) {
    for (uint32_t h = 0; h < 0x10000u; ++h) {
        const float f = floatFromHalf(uint16_t(h));
        if (std::isnan(f)) {
            EXPECT_TRUE(std::isnan(floatFromHalf(halfFromFloat(f)))) << std::hex << h;
        } else if (std::isinf(f)) {
            EXPECT_EQ(floatFromHalf(halfFromFloat(f)), std::copysign(kHalfMax, f)) << "saturates";
        } else {
            EXPECT_EQ(halfFromFloat(f), uint16_t(h)) << std::hex << h;
        }
    }
}

TEST(HalfFloat, DecodesKnownValues) {
    EXPECT_EQ(floatFromHalf(0x3c00u), 1.0f);
    EXPECT_EQ(floatFromHalf(0xc000u), -2.0f);
    EXPECT_EQ(floatFromHalf(0x7bffu), 65504.0f);
    EXPECT_EQ(floatFromHalf(0x0400u), std::ldexp(1.0f, -14));  // the smallest normal
    EXPECT_EQ(floatFromHalf(0x0001u), std::ldexp(1.0f, -24));  // the smallest subnormal
    EXPECT_TRUE(std::isinf(floatFromHalf(0x7c00u)));
}

// Between two neighbouring halves, a float rounds to the nearer, and a tie to the even one.
TEST(HalfFloat, RoundsToNearestEven) {
    for (const uint16_t low : {uint16_t(0x3c00u), uint16_t(0x3c01u), uint16_t(0x0001u), uint16_t(0x0002u),
                               uint16_t(0x03ffu), uint16_t(0x7bfeu)}) {
        const float a = floatFromHalf(low), b = floatFromHalf(uint16_t(low + 1u));
        const float middle = 0.5f * (a + b);
        const uint16_t even = (low & 1u) ? uint16_t(low + 1u) : low;
        EXPECT_EQ(halfFromFloat(middle), even) << std::hex << low;
        EXPECT_EQ(halfFromFloat(std::nextafter(middle, a)), low) << std::hex << low;
        EXPECT_EQ(halfFromFloat(std::nextafter(middle, b)), uint16_t(low + 1u)) << std::hex << low;
        EXPECT_EQ(halfFromFloat(-middle), uint16_t(even | 0x8000u)) << "sign";
    }
    EXPECT_EQ(halfFromFloat(std::ldexp(1.0f, -25)), 0u) << "half the smallest subnormal ties to 0";
    EXPECT_EQ(halfFromFloat(std::ldexp(1.1f, -25)), 1u);
}

// halfFromFloat against rounding done in double arithmetic: the value on half's grid nearest
// to f, ties to even (std::nearbyint's default), for every 251st float (a stride prime to
// the mantissa's bits, so every rounding case is met) of both signs and every exponent.
TEST(HalfFloat, RoundsFloatsAsDoubleArithmeticDoes) {
    size_t checked = 0;
    for (uint64_t bits = 0; bits < (uint64_t(1) << 32); bits += 251) {
        const float f = bitsFloat(uint32_t(bits));
        if (!std::isfinite(f)) continue;
        const double magnitude = std::fabs(double(f));
        const int exponent = magnitude < std::ldexp(1.0, -14) ? -14 : std::ilogb(magnitude);
        const double spacing = std::ldexp(1.0, exponent - 10);
        const double nearest = std::min(std::nearbyint(magnitude / spacing) * spacing, double(kHalfMax));
        const uint16_t expected = uint16_t(halfFromFloat(float(nearest)) | (std::signbit(f) ? 0x8000u : 0u));
        ASSERT_EQ(floatFromHalf(expected), float(std::copysign(nearest, double(f))))
            << "the grid value is a half";
        ASSERT_EQ(halfFromFloat(f), expected) << std::hexfloat << f;
        ++checked;
    }
    EXPECT_GT(checked, 16000000u);
}

TEST(HalfFloat, SaturatesAtTheLargestHalf) {
    EXPECT_EQ(halfFromFloat(65519.0f), 0x7bffu);
    EXPECT_EQ(halfFromFloat(65520.0f), 0x7bffu) << "would round to infinity";
    EXPECT_EQ(halfFromFloat(1e30f), 0x7bffu);
    EXPECT_EQ(halfFromFloat(-std::numeric_limits<float>::infinity()), 0xfbffu);
    EXPECT_TRUE(std::isnan(floatFromHalf(halfFromFloat(std::nanf("")))));
}

TEST(DenoisePlanes, FilteredRadianceGivesBackWhatPackingTookOff) {
    const DenoiseSample bright{{1.2345678f, 1e5f, 3e-7f}, 0.01f};
    const denoise::PackedSample packed = denoise::packSample(bright);
    const Vec3 back = denoise::filteredRadiance(bright, packed);  // a filter that changed nothing
    EXPECT_FLOAT_EQ(back.x, bright.radiance.x);
    EXPECT_FLOAT_EQ(back.y, bright.radiance.y) << "past half's range";
    EXPECT_NEAR(back.z, bright.radiance.z, 1e-12f);
    EXPECT_NEAR(denoise::unpackSample(packed).variance, 0.01f, 0.01f * 1e-3f);
    EXPECT_FALSE(denoise::unpackSample(denoise::packSample({Vec3(1.0f), denoise::kInvalid})).valid());
}

}  // namespace
}  // namespace pt
