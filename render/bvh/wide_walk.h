#pragma once
// The CPU's walk of an 8-wide BVH (wide_bvh.h; issue 21) at SSE2, which every x86-64 CPU runs:
// slab tests take a node's eight child boxes four at a time, the children hit are visited
// nearest first, and leaves go to a leaf functor (a sphere BLAS's is the binary walk's,
// bvh_walk.h; a triangle BLAS's tests blocks of four, triangle_block_intersect.h), so the hits
// found are the binary walk's. Each lane computes exactly what intersectBox computes for that
// box (the same zero-axis origins, the same exit scale, min/max with the same operand order),
// so the box test is as conservative as the binary one and hits stay exact. Where the CPU runs
// AVX2, triangle BLASes take the same loop with a 256-bit test (wide_walk_simd.h).
#if defined(__CUDACC__)
#error "wide_walk.h is CPU code: CUDA translation units walk the binary BVH"
#endif
#include <emmintrin.h>

#include <cstdint>

#include "render/bvh/bvh_walk.h"
#include "render/bvh/triangle_block_intersect.h"
#include "render/kernel/wide_bvh_node.h"

namespace pt {

// Entries on the wide walk's stack: a node (count 0) or a leaf, with where the ray enters it.
// Each node pushes at most kWidth - 1 entries beyond the one it replaces, and no leaf lies
// deeper than kBvhStackSize binary levels, so (kWidth - 1) * kBvhStackSize + kWidth entries
// always suffice.
constexpr uint32_t kWideStackSize = (WideBvhNode::kWidth - 1) * kBvhStackSize + WideBvhNode::kWidth;

struct WideSlabRay {
    __m128 oLoX, oLoY, oLoZ, oHiX, oHiY, oHiZ, invX, invY, invZ;
};

inline WideSlabRay wideSlabRay(const TraversalRay& ray) {
    return {
        _mm_set1_ps(ray.slabOriginLo.x), _mm_set1_ps(ray.slabOriginLo.y), _mm_set1_ps(ray.slabOriginLo.z),
        _mm_set1_ps(ray.slabOriginHi.x), _mm_set1_ps(ray.slabOriginHi.y), _mm_set1_ps(ray.slabOriginHi.z),
        _mm_set1_ps(ray.invDirection.x), _mm_set1_ps(ray.invDirection.y), _mm_set1_ps(ray.invDirection.z)};
}

// intersectBox on four boxes (slots half * 4 .. half * 4 + 3): the lanes that hit, as a 4-bit
// mask, and their entry distances.
inline int intersectWideBoxes(const WideSlabRay& r, const WideBvhNode& n, uint32_t half, float tMax,
                              __m128& tEntry) {
    const uint32_t o = half * 4;
    const __m128 x0 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.loX + o), r.oLoX), r.invX);
    const __m128 x1 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.hiX + o), r.oHiX), r.invX);
    const __m128 y0 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.loY + o), r.oLoY), r.invY);
    const __m128 y1 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.hiY + o), r.oHiY), r.invY);
    const __m128 z0 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.loZ + o), r.oLoZ), r.invZ);
    const __m128 z1 = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.hiZ + o), r.oHiZ), r.invZ);
    // _mm_min_ps(a, b) is a < b ? a : b and _mm_max_ps(a, b) a > b ? a : b: minFast and maxFast.
    const __m128 tNear = _mm_max_ps(_mm_max_ps(_mm_min_ps(x0, x1), _mm_min_ps(y0, y1)),
                                    _mm_max_ps(_mm_min_ps(z0, z1), _mm_setzero_ps()));
    const __m128 tFar =
        _mm_mul_ps(_mm_min_ps(_mm_max_ps(x0, x1), _mm_min_ps(_mm_max_ps(y0, y1), _mm_max_ps(z0, z1))),
                   _mm_set1_ps(kSlabExitScale));
    const __m128 limit = _mm_min_ps(tFar, _mm_set1_ps(tMax * kSlabExitScale));
    // Unused slots (count kEmpty) never hit, whatever their boxes give.
    const __m128i unused = _mm_cmpeq_epi32(_mm_load_si128(reinterpret_cast<const __m128i*>(n.count + o)),
                                           _mm_set1_epi32(int(WideBvhNode::kEmpty)));
    tEntry = tNear;
    return _mm_movemask_ps(_mm_andnot_ps(_mm_castsi128_ps(unused), _mm_cmple_ps(tNear, limit)));
}

// All eight slots, as two halves: the lanes that hit, as an 8-bit mask, and their entries.
inline int intersectWideNode(const WideSlabRay& r, const WideBvhNode& n, float tMax, float* entry) {
    __m128 low, high;
    const int hits = intersectWideBoxes(r, n, 0, tMax, low) | (intersectWideBoxes(r, n, 1, tMax, high) << 4);
    _mm_store_ps(entry, low);
    _mm_store_ps(entry + 4, high);
    return hits;
}

// An entry of the wide walk: a node (count 0) or a leaf, with where the ray enters it.
struct WideWalkEntry {
    uint32_t child, count;
    float entry;
};

// walkWideBvh, the loop over the nodes, with the SSE test above, and walkTriangleBlocks.
#include "render/bvh/wide_walk_loop.inl"

}  // namespace pt
