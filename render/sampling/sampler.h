#pragma once
// Sample values as a pure function of (pixel, sample index, dimension, seed), so every
// backend draws the same numbers and images can be compared pixel by pixel.
//
// The sequence is Owen-scrambled Sobol with hash-based nested uniform scrambling, shuffled
// per pixel and padded in 4-dimensional groups (Burley, "Practical Hash-based Owen
// Scrambling", JCGT 2020). Each group of 4 dimensions uses the first four Sobol dimensions
// with an independent shuffle and scramble, so any 2D pair within a group is well
// stratified, and groups stay uncorrelated.
#include <cstdint>

#include "render/math/vec.h"
#include "render/sampling/hash.h"

namespace pt {

namespace sobol_detail {

// Direction numbers of Sobol dimensions 0-3 (Joe and Kuo), most significant bit first.
inline constexpr uint32_t kSobolDirections[4][32] = {
    // clang-format off
    {0x80000000u, 0x40000000u, 0x20000000u, 0x10000000u, 0x08000000u, 0x04000000u, 0x02000000u, 0x01000000u, 0x00800000u, 0x00400000u, 0x00200000u, 0x00100000u, 0x00080000u, 0x00040000u, 0x00020000u, 0x00010000u, 0x00008000u, 0x00004000u, 0x00002000u, 0x00001000u, 0x00000800u, 0x00000400u, 0x00000200u, 0x00000100u, 0x00000080u, 0x00000040u, 0x00000020u, 0x00000010u, 0x00000008u, 0x00000004u, 0x00000002u, 0x00000001u},
    {0x80000000u, 0xc0000000u, 0xa0000000u, 0xf0000000u, 0x88000000u, 0xcc000000u, 0xaa000000u, 0xff000000u, 0x80800000u, 0xc0c00000u, 0xa0a00000u, 0xf0f00000u, 0x88880000u, 0xcccc0000u, 0xaaaa0000u, 0xffff0000u, 0x80008000u, 0xc000c000u, 0xa000a000u, 0xf000f000u, 0x88008800u, 0xcc00cc00u, 0xaa00aa00u, 0xff00ff00u, 0x80808080u, 0xc0c0c0c0u, 0xa0a0a0a0u, 0xf0f0f0f0u, 0x88888888u, 0xccccccccu, 0xaaaaaaaau, 0xffffffffu},
    {0x80000000u, 0xc0000000u, 0x60000000u, 0x90000000u, 0xe8000000u, 0x5c000000u, 0x8e000000u, 0xc5000000u, 0x68800000u, 0x9cc00000u, 0xee600000u, 0x55900000u, 0x80680000u, 0xc09c0000u, 0x60ee0000u, 0x90550000u, 0xe8808000u, 0x5cc0c000u, 0x8e606000u, 0xc5909000u, 0x6868e800u, 0x9c9c5c00u, 0xeeee8e00u, 0x5555c500u, 0x8000e880u, 0xc0005cc0u, 0x60008e60u, 0x9000c590u, 0xe8006868u, 0x5c009c9cu, 0x8e00eeeeu, 0xc5005555u},
    {0x80000000u, 0xc0000000u, 0x20000000u, 0x50000000u, 0xf8000000u, 0x74000000u, 0xa2000000u, 0x93000000u, 0xd8800000u, 0x25400000u, 0x59e00000u, 0xe6d00000u, 0x78080000u, 0xb40c0000u, 0x82020000u, 0xc3050000u, 0x208f8000u, 0x51474000u, 0xfbea2000u, 0x75d93000u, 0xa0858800u, 0x914e5400u, 0xdbe79e00u, 0x25db6d00u, 0x58800080u, 0xe54000c0u, 0x79e00020u, 0xb6d00050u, 0x800800f8u, 0xc00c0074u, 0x200200a2u, 0x50050093u},
    // clang-format on
};

// The Sobol generator matrices applied one index byte at a time: 4 lookups instead of a
// 32-step loop (an Owen-shuffled index has all 32 bits set at random). 16 KiB. The tables map
// a bit-reversed index to the bit-reversed point, which is what the nested uniform scrambles on
// either side of the lookup take and give (their first and last reversal cancel those of the
// index and the point; the generator matrices are linear over XOR, so the reversal of a point
// is the XOR of the reversed direction numbers): sampleDimension reverses bits twice, not four
// times.
struct SobolByteTables {
    uint32_t entries[4][4][256];  // [dimension][byte of the reversed index][byte value]
};

// reverseBits (hash.h) for the tables' constant evaluation, which its device branch (__brev)
// cannot take part in.
constexpr uint32_t reverseBitsConstexpr(uint32_t x) {
    uint32_t r = 0;
    for (uint32_t bit = 0; bit < 32; ++bit) r |= ((x >> bit) & 1u) << (31 - bit);
    return r;
}

constexpr SobolByteTables makeSobolByteTables() {
    SobolByteTables tables{};
    for (uint32_t dim = 0; dim < 4; ++dim) {
        for (uint32_t byte = 0; byte < 4; ++byte) {
            for (uint32_t value = 0; value < 256; ++value) {
                uint32_t x = 0;
                for (uint32_t bit = 0; bit < 8; ++bit) {
                    // Bit j of the reversed index is bit 31 - j of the index.
                    const uint32_t indexBit = 31 - (byte * 8 + bit);
                    if ((value >> bit) & 1u) x ^= reverseBitsConstexpr(kSobolDirections[dim][indexBit]);
                }
                tables.entries[dim][byte][value] = x;
            }
        }
    }
    return tables;
}

#if defined(__CUDACC__)
__device__ const SobolByteTables kSobolByteTables = makeSobolByteTables();
#else
inline constexpr SobolByteTables kSobolByteTables = makeSobolByteTables();
#endif

// reverseBits(sobol point of index reverseBits(reversedIndex)) in dimension `dim`.
PT_HD uint32_t sobolReversed(uint32_t reversedIndex, uint32_t dim) {
    const auto& t = kSobolByteTables.entries[dim];
    return t[0][reversedIndex & 0xffu] ^ t[1][(reversedIndex >> 8) & 0xffu] ^
           t[2][(reversedIndex >> 16) & 0xffu] ^ t[3][reversedIndex >> 24];
}

// Laine-Karras style permutation, as refined by Burley (2020), listing 2.
PT_HD uint32_t laineKarrasPermutation(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Burley's nested uniform scramble is reverseBits(laineKarrasPermutation(reverseBits(x), seed));
// sampleDimension applies it with the reversals folded into the Sobol tables.

}  // namespace sobol_detail

// Dimension layout of one path, so every stage draws from its own dimensions. 2D needs sit
// on the first two dimensions of a 4D group: Sobol's dimensions 0 and 1 form a (0,2)-sequence,
// so those pairs are stratified in every elementary interval; dimensions 2 and 3 are not.
struct SampleDims {
    static constexpr uint32_t kPixel = 0;  // 2: pixel filter jitter
    static constexpr uint32_t kLens = 2;   // 2: thin-lens aperture
    static constexpr uint32_t kFirstBounce = 4;
    static constexpr uint32_t kPerBounce = 8;   // per bounce, relative to the bounce's base:
    static constexpr uint32_t kLightPoint = 0;  //   2: where on the emitter
    static constexpr uint32_t kLightPick = 2;   //   1: which emitter
    static constexpr uint32_t kBsdfLobe = 3;    //   1: which lobe / reflect or refract
    static constexpr uint32_t kBsdfDir = 4;     //   2: BSDF direction
    static constexpr uint32_t kRoulette = 6;    //   1: Russian roulette
    static constexpr uint32_t kWavelength = 7;  //   1: a dispersive surface's wavelength (dispersion.h)
    PT_HD static uint32_t bounce(uint32_t depth) { return kFirstBounce + depth * kPerBounce; }
    // Stochastic transparency (alpha blend) draws one number per surface a segment passes, up
    // to kAlphaLayers per segment; these dimensions lie beyond any path's own, so they are
    // hashed rather than stratified, which is all a coin flip needs.
    static constexpr uint32_t kAlphaLayers = 64;
    static constexpr uint32_t kAlphaBase = 1u << 24;
    PT_HD static uint32_t alpha(uint32_t depth, uint32_t layer) {
        return kAlphaBase + depth * 2 * kAlphaLayers + layer;
    }
    PT_HD static uint32_t shadowAlpha(uint32_t depth, uint32_t layer) {
        return kAlphaBase + depth * 2 * kAlphaLayers + kAlphaLayers + layer;
    }
    // Segments inside scattering media (medium_scattering.h): 8 dimensions per segment, named by
    // the surface interactions and the medium scattering events before it and the surfaces it
    // passed since (alpha, index-matched boundaries); hashed beyond the alpha dimensions.
    static constexpr uint32_t kMaxMediumBounces = 1024;  // a random walk ends after this many
    static constexpr uint32_t kMediumBase = 1u << 25;
    static constexpr uint32_t kMediumLightPoint = 0;  //   2: where on the emitter
    static constexpr uint32_t kMediumChannel = 2;     //   1: which channel's free flight
    static constexpr uint32_t kMediumDistance = 3;    //   1: its distance
    static constexpr uint32_t kMediumPhaseDir = 4;    //   2: the phase function's direction
    static constexpr uint32_t kMediumLightPick = 6;   //   1: which emitter
    static constexpr uint32_t kMediumRoulette = 7;    //   1: Russian roulette
    PT_HD static uint32_t medium(uint32_t depth, uint32_t mediumBounces, uint32_t passed) {
        return kMediumBase +
               ((depth * (kMaxMediumBounces + 1) + mediumBounces) * (kAlphaLayers + 1) + passed) * 8;
    }
};

namespace sobol_detail {

// What every sample of a path shares: the render's seed hashed with the pixel.
PT_HD uint32_t pixelSeedOf(uint32_t pixel, uint32_t seed) { return hashCombine(hashU32(seed), pixel); }

// What the four dimensions of a group share: the group's seed and the sample index shuffled by
// it (a nested uniform scramble), kept bit-reversed as sobolReversed takes it.
struct SobolGroup {
    uint32_t seed, reversedShuffledIndex;
};

PT_HD SobolGroup sobolGroup(uint32_t pixelSeed, uint32_t sampleIndex, uint32_t group) {
    const uint32_t groupSeed = hashCombine(pixelSeed, group);
    return {groupSeed, laineKarrasPermutation(reverseBits(sampleIndex), groupSeed)};
}

// The shuffled index's Sobol point in dimension `dim` (0-3) of the group, scrambled again with
// a seed of its own.
PT_HD float sobolGroupValue(const SobolGroup& group, uint32_t dim) {
    const uint32_t reversedPoint = sobolReversed(group.reversedShuffledIndex, dim);
    return uintToUnitFloat(
        reverseBits(laineKarrasPermutation(reversedPoint, hashCombine(group.seed, dim + 1))));
}

}  // namespace sobol_detail

// A per-path view of sampleDimension (below) for one pixel and sample: the pixel's share of the
// hashing done once, and a pair within a group drawn from one shuffle.
struct PathSampler {
    uint32_t pixel, sampleIndex;
    uint32_t pixelSeed;  // sobol_detail::pixelSeedOf(pixel, the render's seed)

    PathSampler() = default;
    PT_HD PathSampler(uint32_t pixel_, uint32_t sampleIndex_, uint32_t seed)
        : pixel(pixel_), sampleIndex(sampleIndex_), pixelSeed(sobol_detail::pixelSeedOf(pixel_, seed)) {}

    PT_HD float get(uint32_t dimension) const {
        using namespace sobol_detail;
        return sobolGroupValue(sobolGroup(pixelSeed, sampleIndex, dimension >> 2), dimension & 3u);
    }
    PT_HD Vec2 get2(uint32_t dimension) const {
        using namespace sobol_detail;
        const uint32_t dim = dimension & 3u;
        if (dim == 3u) return {get(dimension), get(dimension + 1)};  // a pair across two groups
        const SobolGroup group = sobolGroup(pixelSeed, sampleIndex, dimension >> 2);
        return {sobolGroupValue(group, dim), sobolGroupValue(group, dim + 1)};
    }
};

// The sample value in [0, 1) for one pixel, sample and dimension. The sample index is shuffled
// by a nested uniform scramble seeded per pixel and group, its Sobol point taken, and that point
// scrambled again, seeded per dimension:
//   scramble(sobol(scramble(sampleIndex, groupSeed), dim), dimSeed),
// with scramble(x, s) = reverseBits(laineKarrasPermutation(reverseBits(x), s)).
PT_HD float sampleDimension(uint32_t pixel, uint32_t sampleIndex, uint32_t dimension, uint32_t seed) {
    return PathSampler(pixel, sampleIndex, seed).get(dimension);
}

}  // namespace pt
