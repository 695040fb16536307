#pragma once
// The walk of a compressed 8-wide BVH (render/kernel/compressed_wide_node.h; issue 21), after
// Ylitie, Karras and Laine 2017, algorithm 1: a node's eight quantised child boxes are tested
// together; the interior children hit form a "node group" (the children's base index with a
// bit per child hit), the primitives of the leaves hit a "primitive group" (base index with a
// bit per primitive), so a node costs one stack entry however many children it hits, and no
// sorting: the bits are numbered in the slot order the collapse chose for the ray's octant,
// which visits near children first. Leaves go to a leaf functor one primitive at a time (a
// triangle BLAS's reads the triangle's corners from its LeafTriangle, leaf_triangle.h, with the
// binary walk's triangle test), and the boxes are conservative (compressed_wide_quantize.h),
// so the hits are the binary walk's.
// Shared by both backends: the CUDA traversal walks it, and the CPU's tests check it.
#if !defined(__CUDACC__)
#include <emmintrin.h>
#endif

#include <cstddef>
#include <cstdint>

#include "render/bvh/bvh_walk.h"
#include "render/bvh/compressed_wide_quantize.h"
#include "render/kernel/compressed_wide_node.h"

namespace pt {

PT_HD uint32_t lowestBit(uint32_t bits) {  // bits != 0
#if defined(__CUDA_ARCH__)
    return uint32_t(__ffs(int(bits)) - 1);
#else
    return uint32_t(__builtin_ctz(bits));
#endif
}

PT_HD uint32_t bitCount(uint32_t bits) {
#if defined(__CUDA_ARCH__)
    return uint32_t(__popc(bits));
#else
    return uint32_t(__builtin_popcount(bits));
#endif
}

// A compressed node's header as the walk reads it: its first eight 32-bit words, two 16-byte
// loads through the read-only path on the GPU. Word 3 holds the exponents (bytes 0-2) and the
// interior mask (byte 3); words 6-7 the leaf metas. The box bytes follow: six words a half node
// (slots 0-3 from word 8, 4-7 from word 14), one for each of loX, loY, loZ, hiX, hiY, hiZ, one
// byte per slot. The child test reads them a half at a time: holding the whole node from three
// 16-byte loads took 18 registers more (ptxas, sm_90: 90 against 72 in the one-instance ray
// kernel).
struct CompressedNodeHeader {
    uint32_t w[8];
};
static_assert(offsetof(CompressedWideNode, childBase) == 16 && offsetof(CompressedWideNode, leafMeta) == 24 &&
                  offsetof(CompressedWideNode, planes) == 32,
              "CompressedNodeHeader, loadHalfBoxes: word indices follow CompressedWideNode's layout");

PT_HD CompressedNodeHeader loadCompressedNodeHeader(const CompressedWideNode* nodes, uint32_t index) {
    CompressedNodeHeader header;
#if defined(__CUDA_ARCH__)
    const uint4* from = reinterpret_cast<const uint4*>(nodes + index);
    for (int i = 0; i < 2; ++i) {
        const uint4 v = __ldg(from + i);
        header.w[4 * i] = v.x, header.w[4 * i + 1] = v.y, header.w[4 * i + 2] = v.z,
                     header.w[4 * i + 3] = v.w;
    }
#else
    __builtin_memcpy(&header, nodes + index, sizeof(header));
#endif
    return header;
}

// The six box words of slots 4 * half to 4 * half + 3, near and far planes chosen per axis
// from the ray's octant (the near planes are the lower ones where the direction is positive).
struct HalfNodeBoxes {
    uint32_t nearX, farX, nearY, farY, nearZ, farZ;
};

PT_HD HalfNodeBoxes loadHalfBoxes(const CompressedWideNode* nodes, uint32_t index, uint32_t half,
                                  uint32_t negative) {
    uint32_t p[6];  // loX, loY, loZ, hiX, hiY, hiZ
#if defined(__CUDA_ARCH__)
    // Words 8-13 or 14-19: a 16-byte and an 8-byte load, in the order their alignment allows.
    const uint32_t* words = reinterpret_cast<const uint32_t*>(nodes + index);
    if (half == 0) {
        const uint4 a = __ldg(reinterpret_cast<const uint4*>(words + 8));
        const uint2 b = __ldg(reinterpret_cast<const uint2*>(words + 12));
        p[0] = a.x, p[1] = a.y, p[2] = a.z, p[3] = a.w, p[4] = b.x, p[5] = b.y;
    } else {
        const uint2 a = __ldg(reinterpret_cast<const uint2*>(words + 14));
        const uint4 b = __ldg(reinterpret_cast<const uint4*>(words + 16));
        p[0] = a.x, p[1] = a.y, p[2] = b.x, p[3] = b.y, p[4] = b.z, p[5] = b.w;
    }
#else
    __builtin_memcpy(p, nodes[index].planes[half], sizeof(p));
#endif
    const bool nx = negative & 1u, ny = negative & 2u, nz = negative & 4u;
    return {nx ? p[3] : p[0], nx ? p[0] : p[3], ny ? p[4] : p[1],
            ny ? p[1] : p[4], nz ? p[5] : p[2], nz ? p[2] : p[5]};
}

// __byte_perm(x, y, selector) on both sides: byte n of the result is byte (nibble n of the
// selector) & 7 of y:x (x's bytes 0-3, y's 4-7). The host's form lets the tests check the
// selectors the GPU uses.
PT_HD uint32_t bytePermute(uint32_t x, uint32_t y, uint32_t selector) {
#if defined(__CUDA_ARCH__)
    return __byte_perm(x, y, selector);
#else
    const uint64_t bytes = uint64_t(y) << 32 | x;
    uint32_t result = 0;
    for (uint32_t n = 0; n < 4; ++n) {
        result |= uint32_t(bytes >> (8 * ((selector >> (4 * n)) & 7u)) & 0xffu) << (8 * n);
    }
    return result;
#endif
}

// Byte k (q) of `word` as 1 + q 2^-15, exactly: q goes into bits 8-15 of the float 1.0
// (bytes 00 00 80 3f), one byte permute on the GPU. The permute takes the constant first: a PRMT
// holds one of its selector and its second word as an immediate, and with the constant second
// ptxas moved each selector into a register first, one instruction more a byte.
PT_HD float byteUnderOne(uint32_t word, uint32_t k) {
    return intAsFloat(int32_t(bytePermute(0x3f800000u, word, 0x3240u + 16u * k)));
}

// Whether the compressed walk can take `ray`. A direction component below 1e-16 has an inverse
// beyond 1e16, up to 1e30 for an exact zero (common: an axis-aligned camera's centre pixel),
// where the walk's plane offsets (origin - o) / d overflow for nodes 3.4e8 away: fma(q, scale, -inf)
// is -inf even where the plane lies on the other side, and a subtree would be culled. The
// binary slab test subtracts before it multiplies and keeps the right sign, so such rays walk
// the binary nodes. Below 1e16 nothing overflows short of coordinates beyond 1e18: offsets
// stay below 2e34, and the GPU test's 2^15 scale (compressedSlotHits) below 6e36.
constexpr float kMaxCompressedInverse = 1e16f;
PT_HD bool compressedWalkTakes(const TraversalRay& ray) {
    return fabsf(ray.invDirection.x) <= kMaxCompressedInverse &&
           fabsf(ray.invDirection.y) <= kMaxCompressedInverse &&
           fabsf(ray.invDirection.z) <= kMaxCompressedInverse;
}

// What the walk precomputes once per ray: for each axis, the origin its near and far planes
// are measured from (TraversalRay's zero-axis padded origins: lower planes from slabOriginLo,
// upper from slabOriginHi) and which of a box's planes is near (the lower one where the
// direction is positive).
struct CompressedWalkRay {
    Vec3 nearOrigin, farOrigin, invDirection;
    uint32_t negative;   // bit a: the direction is negative along axis a (the ray's octant)
    uint32_t firstSlot;  // the slot visited first: the one towards the octant the ray comes from
};

PT_HD CompressedWalkRay compressedWalkRay(const TraversalRay& ray) {
    CompressedWalkRay r;
    r.invDirection = ray.invDirection;
    r.negative = 0;
    for (int a = 0; a < 3; ++a) {
        const bool negative = ray.invDirection[a] < 0.0f;
        r.negative |= uint32_t(negative) << a;
        r.nearOrigin[a] = negative ? ray.slabOriginHi[a] : ray.slabOriginLo[a];
        r.farOrigin[a] = negative ? ray.slabOriginLo[a] : ray.slabOriginHi[a];
    }
    r.firstSlot = r.negative ^ 7u;
    return r;
}

// The children of `node` the ray enters before tMax: the interior ones as bits numbered
// slot ^ firstSlot (the visiting order), the leaves' primitives as bits numbered from primBase.
struct ChildHits {
    uint32_t interior;
    uint32_t primitives;
};

// A plane q steps from a node's origin lies at t = q * scale + offset: scale = 2^e / d is exact
// (clamped where it would overflow), offset = (origin - o) / d, for the near and far planes.
// The clamp: the largest finite float, so that a scale stays finite and keeps its sign.
constexpr float kMaxPlaneScale = 3.4028235e38f;
struct NodePlanes {
    Vec3 scale, nearOffset, farOffset;
};

PT_HD NodePlanes nodePlanes(const CompressedWalkRay& r, const CompressedNodeHeader& node) {
    NodePlanes p;
    for (int a = 0; a < 3; ++a) {
        const uint32_t exponent = (node.w[3] >> (8 * a)) & 0xffu;
        p.scale[a] = clampf(exponentStep(exponent) * r.invDirection[a], -kMaxPlaneScale, kMaxPlaneScale);
        const float origin = intAsFloat(int32_t(node.w[a]));
        p.nearOffset[a] = (origin - r.nearOrigin[a]) * r.invDirection[a];
        p.farOffset[a] = (origin - r.farOrigin[a]) * r.invDirection[a];
    }
    return p;
}

// `slotBits` (bit s: slot s) renumbered in the ray's visiting order: bit s ^ firstSlot. XOR
// by a constant permutes the bits in three conditional swaps (of neighbours, pairs, halves).
PT_HD uint32_t inVisitingOrder(uint32_t slotBits, uint32_t firstSlot) {
    uint32_t m = slotBits;
    if (firstSlot & 1u) m = ((m & 0x55u) << 1) | ((m >> 1) & 0x55u);
    if (firstSlot & 2u) m = ((m & 0x33u) << 2) | ((m >> 2) & 0x33u);
    if (firstSlot & 4u) m = ((m & 0x0fu) << 4) | ((m >> 4) & 0x0fu);
    return m;
}

// The primitive bits of a leaf slot's meta byte, (count << 5) | offset from primBase: count
// bits from offset. Interior and unused slots have count 0 and give none, whatever their (zero)
// box gives.
PT_HD uint32_t leafPrimitiveBits(uint32_t meta) { return ((1u << (meta >> 5)) - 1u) << (meta & 31u); }

// The hits of the slots whose bits are set in `slotHits`, sorted into interior children and
// leaf primitives. The leaves' bits are gathered for the leaf slots hit alone: the GPU's test
// gathered them for every slot in its loop (about six operations of a slot's forty, by count in
// the source), where a node's leaf slots hit are few; gathered here, bench's rays of the 1M
// sphere at 1080p on an H200 ran 1.08x, 1.15x and 1.33x as fast as the binary walk's (primary,
// diffuse, shadow), from 1.01x, 1.00x and 1.21x. The meta word is chosen by a select: indexed,
// node.w[6 + half] put the header in local memory.
PT_HD ChildHits classifyHits(const CompressedWalkRay& r, const CompressedNodeHeader& node,
                             uint32_t slotHits) {
    ChildHits hits{inVisitingOrder(slotHits & (node.w[3] >> 24), r.firstSlot), 0u};
    for (uint32_t leaves = slotHits & ~(node.w[3] >> 24); leaves != 0; leaves &= leaves - 1) {
        const uint32_t slot = lowestBit(leaves);
        const uint32_t metas = slot >= 4 ? node.w[7] : node.w[6];
        hits.primitives |= leafPrimitiveBits((metas >> (8 * (slot & 3u))) & 0xffu);
    }
    return hits;
}

#if !defined(__CUDACC__)
// The host's form of the child test, for the host's walks of the GPU's tree (the tests): four
// slots a time with SSE2 (part of every x86-64 CPU). It rounds q * scale and the sum apart, one
// rounding more than fma(q, scale, offset), which the planes' step of margin covers as well
// (compressed_wide_quantize.h): the boxes stay conservative and the hits exact, so both
// backends find the same hits. The GPU's form is compressedSlotHits, below.
inline __m128 bytesAsFloats(uint32_t word) {
    const __m128i zero = _mm_setzero_si128();
    const __m128i bytes = _mm_cvtsi32_si128(int32_t(word));
    return _mm_cvtepi32_ps(_mm_unpacklo_epi16(_mm_unpacklo_epi8(bytes, zero), zero));
}

inline ChildHits intersectCompressedChildren(const CompressedWalkRay& r, const CompressedNodeHeader& node,
                                             const CompressedWideNode* nodes, uint32_t index, float tMax) {
    const NodePlanes p = nodePlanes(r, node);
    const __m128 scaleX = _mm_set1_ps(p.scale.x), scaleY = _mm_set1_ps(p.scale.y),
                 scaleZ = _mm_set1_ps(p.scale.z);
    const __m128 nearX = _mm_set1_ps(p.nearOffset.x), nearY = _mm_set1_ps(p.nearOffset.y),
                 nearZ = _mm_set1_ps(p.nearOffset.z);
    const __m128 farX = _mm_set1_ps(p.farOffset.x), farY = _mm_set1_ps(p.farOffset.y),
                 farZ = _mm_set1_ps(p.farOffset.z);
    const __m128 limit = _mm_set1_ps(tMax * kSlabExitScale), exitScale = _mm_set1_ps(kSlabExitScale);
    uint32_t slotHits = 0;
    for (uint32_t half = 0; half < 2; ++half) {
        const HalfNodeBoxes b = loadHalfBoxes(nodes, index, half, r.negative);
        const __m128 x0 = _mm_add_ps(_mm_mul_ps(bytesAsFloats(b.nearX), scaleX), nearX);
        const __m128 x1 = _mm_add_ps(_mm_mul_ps(bytesAsFloats(b.farX), scaleX), farX);
        const __m128 y0 = _mm_add_ps(_mm_mul_ps(bytesAsFloats(b.nearY), scaleY), nearY);
        const __m128 y1 = _mm_add_ps(_mm_mul_ps(bytesAsFloats(b.farY), scaleY), farY);
        const __m128 z0 = _mm_add_ps(_mm_mul_ps(bytesAsFloats(b.nearZ), scaleZ), nearZ);
        const __m128 z1 = _mm_add_ps(_mm_mul_ps(bytesAsFloats(b.farZ), scaleZ), farZ);
        // _mm_min_ps(a, b) is a < b ? a : b and _mm_max_ps(a, b) a > b ? a : b: minFast and maxFast.
        const __m128 tNear = _mm_max_ps(_mm_max_ps(x0, y0), _mm_max_ps(z0, _mm_setzero_ps()));
        const __m128 tFar = _mm_mul_ps(_mm_min_ps(x1, _mm_min_ps(y1, z1)), exitScale);
        slotHits |= uint32_t(_mm_movemask_ps(_mm_cmple_ps(tNear, _mm_min_ps(tFar, limit)))) << (4 * half);
    }
    return classifyHits(r, node, slotHits);
}
#endif

// The GPU's child test: each of a node's 48 plane distances in one FFMA. With f = 1 + q 2^-15
// (byteUnderOne), S = 2^15 scale and O = offset - S for the node, fma(f, S, O) =
// q scale + offset + e, where e, O's rounding, is at most u (|offset| + 2^15 |scale|). Of that,
// u 2^15 |scale| is 2^-9 of a grid step, which the planes' step of margin covers
// (compressed_wide_quantize.h), and u |offset| <= u (|t| + 255 steps) is one rounding of the
// distance more than fma(q, scale, offset) makes, which kCompressedExitScale's gamma(4) covers
// where the binary walk's gamma(3) covers three. The first form here subtracted 2^23 from each
// byte, one instruction more a plane (Ylitie et al. 2017, section 4: conversions issue at a
// quarter of the rate); without it camera rays of a 1M-triangle sphere took 341M instructions
// instead of 358M (ncu, H200, 1080p), and bench's rays ran 3542-3590 / 2070-2079 / 1640-1662
// Mrays/s (camera / diffuse / shadow, two runs) against 3483-3524 / 2045-2048 / 1594-1598.
// The host runs it in the tests (compressed_wide_bvh_test.cpp), with its own fused
// multiply-add.
constexpr float kCompressedExitScale = 1.0f + 2.0f * gammaBound(4);

// Bit s: slot s's box is entered before tMax (whatever the slot holds).
PT_HD uint32_t compressedSlotHits(const CompressedWalkRay& r, const CompressedNodeHeader& node,
                                  const CompressedWideNode* nodes, uint32_t index, float tMax) {
    const NodePlanes p = nodePlanes(r, node);
    Vec3 scale, nearOffset, farOffset;
    for (int a = 0; a < 3; ++a) {
        scale[a] = clampf(p.scale[a] * 32768.0f, -kMaxPlaneScale, kMaxPlaneScale);
        nearOffset[a] = p.nearOffset[a] - scale[a];
        farOffset[a] = p.farOffset[a] - scale[a];
    }
    const float limit = tMax * kCompressedExitScale;
    uint32_t slotHits = 0;
    // Half a node at a time: unrolled, the compiler loads both halves' boxes up front and keeps
    // them live (84 registers against 72 in the one-instance ray kernel). The half's four bits
    // are gathered at fixed shifts and placed once: shifted by 4 * half + k each, every bit took
    // its own shift amount (ptxas, sm_90).
    PT_NO_UNROLL
    for (uint32_t half = 0; half < 2; ++half) {
        const HalfNodeBoxes b = loadHalfBoxes(nodes, index, half, r.negative);
        uint32_t halfHits = 0;
        for (uint32_t k = 0; k < 4; ++k) {
            const float x0 = fmaf(byteUnderOne(b.nearX, k), scale.x, nearOffset.x);
            const float x1 = fmaf(byteUnderOne(b.farX, k), scale.x, farOffset.x);
            const float y0 = fmaf(byteUnderOne(b.nearY, k), scale.y, nearOffset.y);
            const float y1 = fmaf(byteUnderOne(b.farY, k), scale.y, farOffset.y);
            const float z0 = fmaf(byteUnderOne(b.nearZ, k), scale.z, nearOffset.z);
            const float z1 = fmaf(byteUnderOne(b.farZ, k), scale.z, farOffset.z);
            const float tNear = maxFast(maxFast(x0, y0), maxFast(z0, 0.0f));
            const float tFar = minFast(x1, minFast(y1, z1)) * kCompressedExitScale;
            halfHits |= uint32_t(tNear <= minFast(tFar, limit)) << k;
        }
        slotHits |= halfHits << (4 * half);
    }
    return slotHits;
}

#if defined(__CUDACC__)
PT_HD ChildHits intersectCompressedChildren(const CompressedWalkRay& r, const CompressedNodeHeader& node,
                                            const CompressedWideNode* nodes, uint32_t index, float tMax) {
    return classifyHits(r, node, compressedSlotHits(r, node, nodes, index, tMax));
}
#endif

// walkBvh over the compressed tree `nodes` from node `root`: `leaf(index, 1, tMax)` tests the
// primitive at `index` of the compressed primitive list, as the binary walk's leaf functor
// tests a range. A node group on the stack holds its children's base, its interior mask and
// the bits of the children hit but not yet visited; popped groups are not culled by distance
// (they keep none), the children's boxes are tested against the current tMax when visited.
//
// On the GPU a thread with primitives to test postpones them (pushes its primitive group) where
// fewer than a fifth of its warp's active threads have any, as Ylitie et al. do (section 4):
// the others would idle while it tests them, and go on down the tree together instead. On an
// H200 at 1080p (bench, 1M-triangle sphere) this took the ray kernel's primary and diffuse rays
// from 2058 and 1125 to 2794 and 1466 Mrays/s (active threads a warp, diffuse: 10.6 to 14.5),
// and its shadow rays from 1256 to 1225; but it cost the megakernel's fused step 5% (525.6 to
// 501.9 spp/s), whose warps reach the walk from shading too: not there (kSharedSite).
constexpr uint32_t kPostponedGroups = 16;  // pushed only while the stack holds fewer entries
constexpr uint32_t kPrimitiveGroup = kCompressedPrimitiveLimit;  // marks a postponed group's base

template <class LeafFn, class Count>
PT_HD bool walkCompressedWideBvh(const CompressedWideNode* nodes, uint32_t root, const TraversalRay& ray,
                                 float& tMax, LeafFn& leaf, Count count, bool anyHit) {
#if defined(__CUDA_ARCH__)
    constexpr bool kPostpone = !kSharedSite<Count>;
#else
    constexpr bool kPostpone = false;
#endif
    const CompressedWalkRay r = compressedWalkRay(ray);
    // Stack entries: a node group's base, and its interior mask << 8 | the bits left to visit;
    // or a postponed primitive group's base | kPrimitiveGroup, and its bits. One node group is
    // pushed per level descended, and no leaf lies deeper than kBvhStackSize; primitive groups
    // are pushed only below kPostponedGroups entries, so at most that many are held.
    constexpr uint32_t kStackSize = kBvhStackSize + (kPostpone ? kPostponedGroups : 0u);
    uint32_t stackBase[kStackSize], stackBits[kStackSize];
    uint32_t size = 0;
    // The root as the one interior child (slot 0) of a group based at it.
    uint32_t groupBase = root, groupInterior = 1u, groupBits = 1u << r.firstSlot;
    uint32_t primBase = 0, primBits = 0;
    bool found = false;
    for (;;) {
        if (groupBits != 0) {
            const uint32_t bit = lowestBit(groupBits);
            groupBits &= groupBits - 1;
            const uint32_t slot = bit ^ r.firstSlot;
            const uint32_t child = groupBase + bitCount(groupInterior & ((1u << slot) - 1u));
            if (groupBits != 0) {
                assert(size < kStackSize && "BVH deeper than the traversal stack");
                stackBase[size] = groupBase;
                stackBits[size++] = groupInterior << 8 | groupBits;
            }
            count.node();
            const CompressedNodeHeader node = loadCompressedNodeHeader(nodes, child);
            const ChildHits hits = intersectCompressedChildren(r, node, nodes, child, tMax);
            groupBase = node.w[4];
            groupInterior = node.w[3] >> 24;
            groupBits = hits.interior;
            primBase = node.w[5];
            primBits = hits.primitives;
        }
        if constexpr (kPostpone) {
            if (rareInWarp(primBits != 0) && primBits != 0 && groupBits != 0 && size < kPostponedGroups) {
                stackBase[size] = primBase | kPrimitiveGroup;
                stackBits[size++] = primBits;
                primBits = 0;
            }
        }
        while (primBits != 0) {
            const uint32_t bit = lowestBit(primBits);
            primBits &= primBits - 1;
            if (leaf(primBase + bit, 1u, tMax)) {
                found = true;
                if (anyHit) return true;
            }
        }
        if (groupBits == 0) {
            if (size == 0) return found;
            --size;
            if (kPostpone && (stackBase[size] & kPrimitiveGroup)) {
                primBase = stackBase[size] & ~kPrimitiveGroup;
                primBits = stackBits[size];
            } else {
                groupBase = stackBase[size];
                groupInterior = stackBits[size] >> 8;
                groupBits = stackBits[size] & 0xffu;
            }
        }
    }
}

}  // namespace pt
