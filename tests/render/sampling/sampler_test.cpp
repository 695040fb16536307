#include "render/sampling/sampler.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace pt {
namespace {

TEST(Sampler, IsAPureFunctionOfItsInputs) {
    for (uint32_t d = 0; d < 32; ++d) {
        EXPECT_EQ(sampleDimension(17, 5, d, 3), sampleDimension(17, 5, d, 3));
    }
    // Changing any one input changes the value (with overwhelming probability).
    EXPECT_NE(sampleDimension(17, 5, 2, 3), sampleDimension(18, 5, 2, 3));
    EXPECT_NE(sampleDimension(17, 5, 2, 3), sampleDimension(17, 6, 2, 3));
    EXPECT_NE(sampleDimension(17, 5, 2, 3), sampleDimension(17, 5, 3, 3));
    EXPECT_NE(sampleDimension(17, 5, 2, 3), sampleDimension(17, 5, 2, 4));
}

TEST(Sampler, ValuesLieInTheHalfOpenUnitInterval) {
    for (uint32_t i = 0; i < 100000; ++i) {
        const float v = sampleDimension(i % 97, i, i % 13, 1);
        ASSERT_GE(v, 0.0f);
        ASSERT_LT(v, 1.0f);
    }
}

// Owen-scrambled Sobol keeps the (0,2)-net property of the first two dimensions of each 4D
// group: the first 2^k samples put exactly one point in each of the 2^k elementary intervals
// of any shape. A hashed (independent) sampler fails this almost surely.
TEST(Sampler, PairsWithinAGroupAreStratifiedInEveryElementaryInterval) {
    constexpr uint32_t kLog = 8, kCount = 1u << kLog;
    for (uint32_t pixel : {0u, 12345u}) {
        for (uint32_t pairStart : {0u, 4u, 8u, 12u}) {
            for (uint32_t xBits = 0; xBits <= kLog; ++xBits) {
                const uint32_t yBits = kLog - xBits;
                std::set<uint32_t> cells;
                for (uint32_t i = 0; i < kCount; ++i) {
                    const float x = sampleDimension(pixel, i, pairStart, 7);
                    const float y = sampleDimension(pixel, i, pairStart + 1, 7);
                    const uint32_t cx = uint32_t(x * float(1u << xBits));
                    const uint32_t cy = uint32_t(y * float(1u << yBits));
                    cells.insert((cx << yBits) | cy);
                }
                EXPECT_EQ(cells.size(), kCount)
                    << "pixel " << pixel << " dims " << pairStart << " shape " << xBits << "x" << yBits;
            }
        }
    }
}

TEST(Sampler, DifferentPixelsGetDecorrelatedSequences) {
    // The mean over pixels of the first sample is uniform, not the same point everywhere.
    double sum = 0.0;
    std::set<float> distinct;
    for (uint32_t pixel = 0; pixel < 4096; ++pixel) {
        const float v = sampleDimension(pixel, 0, 0, 0);
        sum += v;
        distinct.insert(v);
    }
    EXPECT_NEAR(sum / 4096.0, 0.5, 0.02);
    EXPECT_GT(distinct.size(), 4000u);
}

}  // namespace
}  // namespace pt

namespace pt {
namespace {

// The byte tables must equal the textbook generator-matrix product, bit by bit.
TEST(Sampler, ByteTableSobolEqualsTheDirectNumberLoop) {
    for (uint32_t dim = 0; dim < 4; ++dim) {
        for (uint32_t i = 0; i < 100000; ++i) {
            const uint32_t index = hashU32(i) ^ i;
            uint32_t expected = 0;
            for (uint32_t bit = 0; bit < 32; ++bit) {
                if ((index >> bit) & 1u) expected ^= sobol_detail::kSobolDirections[dim][bit];
            }
            ASSERT_EQ(sobol_detail::sobol(index, dim), expected) << "dim " << dim << " index " << index;
        }
    }
    EXPECT_EQ(sobol_detail::sobol(1, 0), 0x80000000u);
    EXPECT_EQ(sobol_detail::sobol(3, 1), 0x40000000u);  // 0x80000000 ^ 0xc0000000
}

}  // namespace
}  // namespace pt
