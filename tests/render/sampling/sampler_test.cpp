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

// The textbook Sobol point: the generator matrix times the index, one direction number a bit.
uint32_t sobolByLoop(uint32_t index, uint32_t dim) {
    uint32_t point = 0;
    for (uint32_t bit = 0; bit < 32; ++bit) {
        if ((index >> bit) & 1u) point ^= sobol_detail::kSobolDirections[dim][bit];
    }
    return point;
}

// Burley's nested uniform scramble, as written in his listing: reversal, permutation, reversal.
uint32_t scrambleByListing(uint32_t x, uint32_t seed) {
    return reverseBits(sobol_detail::laineKarrasPermutation(reverseBits(x), seed));
}

// The sample value as sampler.h defines it, computed the textbook way:
// scramble(sobol(scramble(sample index, group seed)), dimension seed).
float definedSampleValue(uint32_t pixel, uint32_t sampleIndex, uint32_t dimension, uint32_t seed) {
    const uint32_t groupSeed = hashCombine(hashCombine(hashU32(seed), pixel), dimension >> 2);
    const uint32_t dim = dimension & 3u;
    const uint32_t point = sobolByLoop(scrambleByListing(sampleIndex, groupSeed), dim);
    return uintToUnitFloat(scrambleByListing(point, hashCombine(groupSeed, dim + 1)));
}

// The byte tables must equal the textbook generator-matrix product, bit by bit, with the index
// and the point bit-reversed as the tables take and give them.
TEST(Sampler, ByteTableSobolEqualsTheDirectNumberLoop) {
    for (uint32_t dim = 0; dim < 4; ++dim) {
        for (uint32_t i = 0; i < 100000; ++i) {
            const uint32_t index = hashU32(i) ^ i;
            ASSERT_EQ(reverseBits(sobol_detail::sobolReversed(reverseBits(index), dim)),
                      sobolByLoop(index, dim))
                << "dim " << dim << " index " << index;
        }
    }
    EXPECT_EQ(sobol_detail::sobolReversed(reverseBits(1u), 0), reverseBits(0x80000000u));
    EXPECT_EQ(sobol_detail::sobolReversed(reverseBits(3u), 1), reverseBits(0x40000000u));  // 0x8.. ^ 0xc..
}

// sampleDimension, with the scrambles' reversals folded into the tables, draws exactly the
// numbers of the sequence as defined (sampler.h): scramble(sobol(scramble(sample index))), so
// images rendered before and after that change, and on either backend, stay equal.
TEST(Sampler, SampleValuesAreThoseOfTheScrambledSobolSequenceAsDefined) {
    for (uint32_t i = 0; i < 200000; ++i) {
        const uint32_t pixel = hashU32(i * 3 + 1), sampleIndex = i % 7 == 0 ? i : hashU32(i) >> (i % 23);
        const uint32_t dimension = i % 71, seed = hashU32(i + 17);
        const float expected = definedSampleValue(pixel, sampleIndex, dimension, seed);
        ASSERT_EQ(floatAsInt(sampleDimension(pixel, sampleIndex, dimension, seed)), floatAsInt(expected))
            << "pixel " << pixel << " sample " << sampleIndex << " dimension " << dimension << " seed "
            << seed;
    }
}

// A path's sampler draws the defined values (sampleDimension is its get): its pixel seed hashed
// once, and a pair within a group (or across two, from a group's last dimension) from one
// shuffle.
TEST(Sampler, PathSamplerDrawsTheValuesOfSampleDimension) {
    for (uint32_t i = 0; i < 20000; ++i) {
        const uint32_t pixel = hashU32(i), sampleIndex = i * 7, seed = i % 5;
        const PathSampler sampler(pixel, sampleIndex, seed);
        for (uint32_t dimension = 0; dimension < 40; ++dimension) {
            const float expected = definedSampleValue(pixel, sampleIndex, dimension, seed);
            ASSERT_EQ(floatAsInt(sampler.get(dimension)), floatAsInt(expected)) << dimension;
            const Vec2 pair = sampler.get2(dimension);
            ASSERT_EQ(floatAsInt(pair.x), floatAsInt(expected)) << dimension;
            ASSERT_EQ(floatAsInt(pair.y),
                      floatAsInt(definedSampleValue(pixel, sampleIndex, dimension + 1, seed)))
                << dimension;
        }
    }
}

}  // namespace
}  // namespace pt
