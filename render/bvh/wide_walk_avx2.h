// The CPU's 8-wide walk at AVX2 (issue 21) and its leaf functor, which tests a leaf's eight
// triangles (two blocks) in one pass, for the files compiled under an AVX2 target pragma:
// wide_walk_avx2.cpp (one ray) and packet_walk_avx2.cpp (eight rays, whose lanes finish alone
// on this walk). Include it only after that pragma, inside no namespace: its functions live in
// pt::avx2, a name no SSE2 code shares, so the linker never takes an AVX2 copy for an SSE2 one
// (wide_walk_avx2.cpp says why the shared headers come before the pragma).
#if defined(__CUDACC__)
#error "wide_walk_avx2.h is CPU code"
#endif
#if !defined(__AVX2__) && !defined(PT_AVX2_TARGET_PRAGMA)
#error "wide_walk_avx2.h: include it under the AVX2 target pragma (define PT_AVX2_TARGET_PRAGMA there)"
#endif
// Its includes must already have come before the pragma (the .cpp includes them first); these
// only state what it uses.
#include <immintrin.h>

#include <cstddef>
#include <limits>

#include "render/bvh/lane_ops.h"
#include "render/bvh/triangle_block_intersect.h"
#include "render/bvh/wide_walk.h"

namespace pt {
namespace avx2 {

// The ray as the 256-bit test takes it. Per axis: which of a node's two planes the ray meets
// first (its lower one where the inverse direction is positive, else its upper one; the
// inverse is 0 only for an infinite direction component, which `fused` turns away), as a byte offset of that
// plane array in the node; and each plane's distance as one fused multiply-add, t = p * inverse + offset,
// where offset = -origin * inverse (the plane's slab origin). pt::intersectWideBoxes subtracts and then
// multiplies: two dependent roundings, and a multiply of the exit by kSlabExitScale after the minimum, on the
// path from a node's load to the choice of the next node, which is the walk's critical path (the node's test
// decides which node is loaded next). The FMA form, with the exit planes' inverse scaled once per ray and
// unused slots culled by their empty boxes (below), took bench's diffuse rays on a 10k-triangle sphere
// from 7.63 to 8.38 Mrays/s and its shadow rays from 8.72 to 9.21 (one thread pinned to a core, three
// alternated runs each).
//
// It stays conservative, so the hits stay exact (the leaves decide them). With u = 2^-24, S =
// kSlabExitScale = 1 + 6u as a float, and T the exact distance to a plane from its slab origin
// (bvh_walk.h's padded origins), on an axis whose direction is not a zero one:
// - the near offset is at most -origin * inverse (wideSlabRay), so the near FMA's exact value
//   p * inverse + offset is at most (p - origin) * inverse = T (1 + e), |e| <= u, the inverse's
//   rounding;
// - the exit planes' inverse is inverse * S rounded and their offset at least -origin * that
//   inverse, so the far FMA's exact value is at least T S (1 + e)(1 + e'), at least T S (1 - u)^2
//   where T >= 0;
// - where the ray enters the box, max(0, near T) <= far T, and S (1 - u)^2 >= 1 + u (1 + 4u -
//   O(u^2) against 1 + u): every near value before rounding is at most every far one, and at
//   most tMax (1 + u) <= tMax * S, and rounding is monotonic (denormals too), so the rounded
//   values compare the same way and no box the ray enters within [0, tMax] is culled. The
//   entries, rounded from at most T (1 + u), stay what the walk's pop test (entry > tMax * S)
//   expects.
// A zero axis (inverse +-1e30) is conservative by sign, as in pt's test: inside the padded slab
// the near distance is below 0 and the far one huge; the offsets' slack (below) widens the pad
// by about half, which costs nothing a finite tMax does not cull.
// The fused test needs finite offsets and a nonzero inverse: an infinite offset would meet an
// unused slot's infinite plane (wide_bvh.cpp's emptyNode) as inf - inf, and an inverse of 0 (an
// infinite direction component) as inf * 0, NaNs that min and max drop, entering the slot. A ray
// with either (|origin * inverse| beyond 3.4e38: coordinates beyond 3.4e8 along a zero axis,
// whose inverse is 1e30) takes pt::intersectWideBoxes' subtract-then-multiply test instead,
// whose mask culls unused slots (`fused` false).
struct WideSlabRay {
    __m256 nearOffsetX, nearOffsetY, nearOffsetZ, farOffsetX, farOffsetY, farOffsetZ;
    __m256 invX, invY, invZ, farInvX, farInvY, farInvZ;
    uint32_t nearX, nearY, nearZ, farX, farY, farZ;
    bool fused;               // finite offsets, nonzero inverses: the FMA test applies
    const TraversalRay* ray;  // for the test of a ray they are not
};

// Each plane offset, -origin * inverse, is rounded (off by at most 2^-24 of it, or half the
// least denormal) and then moved by 2^-21 of itself and the least denormal, down for the entry
// planes and up for the exit planes: eight times the rounding, so that after the move's own
// roundings it is still beyond the exact product, and no branch on which way it rounded (a
// coin toss a ray: computed exactly in double and stepped a float where it fell short, one axis
// at a time, the set-up's mispredictions ate the node test's gain). All three axes go through
// SSE together: this runs once a ray.
inline WideSlabRay wideSlabRay(const TraversalRay& ray) {
    constexpr uint32_t kAxisBytes = sizeof(WideBvhNode::loX);
    const __m128 inverse = _mm_setr_ps(ray.invDirection.x, ray.invDirection.y, ray.invDirection.z, 1.0f);
    const __m128 originLo = _mm_setr_ps(ray.slabOriginLo.x, ray.slabOriginLo.y, ray.slabOriginLo.z, 0.0f);
    const __m128 originHi = _mm_setr_ps(ray.slabOriginHi.x, ray.slabOriginHi.y, ray.slabOriginHi.z, 0.0f);
    const __m128 positive = _mm_cmpgt_ps(inverse, _mm_setzero_ps());
    const __m128 farInverse = _mm_mul_ps(inverse, _mm_set1_ps(kSlabExitScale));
    const __m128 nearProduct = _mm_mul_ps(_mm_blendv_ps(originHi, originLo, positive), inverse);
    const __m128 farProduct = _mm_mul_ps(_mm_blendv_ps(originLo, originHi, positive), farInverse);
    const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
    const auto slack = [magnitude](__m128 v) {
        return _mm_add_ps(_mm_mul_ps(_mm_and_ps(v, magnitude), _mm_set1_ps(0x1p-21f)),
                          _mm_set1_ps(0x1p-149f));
    };
    const __m128 nearOffsets = _mm_sub_ps(_mm_sub_ps(_mm_setzero_ps(), nearProduct), slack(nearProduct));
    const __m128 farOffsets = _mm_add_ps(_mm_sub_ps(_mm_setzero_ps(), farProduct), slack(farProduct));
    alignas(16) float nearOffset[4], farOffset[4], farInv[4];
    _mm_store_ps(nearOffset, nearOffsets);
    _mm_store_ps(farOffset, farOffsets);
    _mm_store_ps(farInv, farInverse);
    const __m128 infinity = _mm_set1_ps(std::numeric_limits<float>::infinity());
    // Finite offsets, and an inverse that is not 0 (NaN compares false on both).
    const __m128 finiteOffsets = _mm_and_ps(_mm_cmplt_ps(_mm_and_ps(nearOffsets, magnitude), infinity),
                                            _mm_cmplt_ps(_mm_and_ps(farOffsets, magnitude), infinity));
    const int finite = _mm_movemask_ps(_mm_and_ps(finiteOffsets, _mm_cmpneq_ps(inverse, _mm_setzero_ps())));
    const int positiveAxes = _mm_movemask_ps(positive);
    WideSlabRay r;
    uint32_t nearPlane[3], farPlane[3];
    for (int a = 0; a < 3; ++a) {
        const uint32_t lo = uint32_t(offsetof(WideBvhNode, loX)) + uint32_t(a) * kAxisBytes;
        const uint32_t hi = uint32_t(offsetof(WideBvhNode, hiX)) + uint32_t(a) * kAxisBytes;
        const uint32_t isPositive = uint32_t(positiveAxes >> a) & 1u;
        nearPlane[a] = isPositive ? lo : hi;
        farPlane[a] = isPositive ? hi : lo;
    }
    r.nearOffsetX = _mm256_set1_ps(nearOffset[0]), r.nearOffsetY = _mm256_set1_ps(nearOffset[1]);
    r.nearOffsetZ = _mm256_set1_ps(nearOffset[2]);
    r.farOffsetX = _mm256_set1_ps(farOffset[0]), r.farOffsetY = _mm256_set1_ps(farOffset[1]);
    r.farOffsetZ = _mm256_set1_ps(farOffset[2]);
    r.invX = _mm256_set1_ps(ray.invDirection.x), r.invY = _mm256_set1_ps(ray.invDirection.y);
    r.invZ = _mm256_set1_ps(ray.invDirection.z);
    r.farInvX = _mm256_set1_ps(farInv[0]), r.farInvY = _mm256_set1_ps(farInv[1]);
    r.farInvZ = _mm256_set1_ps(farInv[2]);
    r.nearX = nearPlane[0], r.nearY = nearPlane[1], r.nearZ = nearPlane[2];
    r.farX = farPlane[0], r.farY = farPlane[1], r.farZ = farPlane[2];
    r.fused = (finite & 7) == 7;
    r.ray = &ray;
    return r;
}

// A node's eight child boxes: the slots the ray enters before tMax, as a bit mask, and their
// entry distances. Unused slots need no mask: their boxes are empty (lower planes +infinity,
// upper ones -infinity), so the near plane's distance is +infinity on every axis and nothing
// is entered.
inline int intersectWideNode(const WideSlabRay& r, const WideBvhNode& n, float tMax, float* entry) {
    if (!r.fused) {
        // pt::intersectWideBoxes: the planes' distances from the unfused subtraction and product
        // (an unused slot's planes give -infinity there, which its mask culls).
        __m128 low, high;
        const pt::WideSlabRay sse = pt::wideSlabRay(*r.ray);
        const int hits = pt::intersectWideBoxes(sse, n, 0, tMax, low) |
                         (pt::intersectWideBoxes(sse, n, 1, tMax, high) << 4);
        _mm_store_ps(entry, low);
        _mm_store_ps(entry + 4, high);
        return hits;
    }
    const char* node = reinterpret_cast<const char*>(&n);
    const auto plane = [node](uint32_t offset) {
        return _mm256_load_ps(reinterpret_cast<const float*>(node + offset));
    };
    const __m256 nx = _mm256_fmadd_ps(plane(r.nearX), r.invX, r.nearOffsetX);
    const __m256 ny = _mm256_fmadd_ps(plane(r.nearY), r.invY, r.nearOffsetY);
    const __m256 nz = _mm256_fmadd_ps(plane(r.nearZ), r.invZ, r.nearOffsetZ);
    const __m256 fx = _mm256_fmadd_ps(plane(r.farX), r.farInvX, r.farOffsetX);
    const __m256 fy = _mm256_fmadd_ps(plane(r.farY), r.farInvY, r.farOffsetY);
    const __m256 fz = _mm256_fmadd_ps(plane(r.farZ), r.farInvZ, r.farOffsetZ);
    // Minima and maxima in pairs, tMax's slack beside the third exit: two levels, not three.
    const __m256 tNear = _mm256_max_ps(_mm256_max_ps(nx, ny), _mm256_max_ps(nz, _mm256_setzero_ps()));
    const __m256 tExit =
        _mm256_min_ps(_mm256_min_ps(fx, fy), _mm256_min_ps(fz, _mm256_set1_ps(tMax * kSlabExitScale)));
    _mm256_store_ps(entry, tNear);
    return _mm256_movemask_ps(_mm256_cmp_ps(tNear, tExit, _CMP_LE_OQ));
}

// triangle_lanes.inl's operations at AVX2: two blocks a test, eight lanes, each comparison
// the predicate of its SSE2 twin (triangle_block_intersect.h), so every lane computes the same.
namespace lane_ops {
using Vector = __m256;
constexpr uint32_t kCount = 8;
PT_LANE_ARITHMETIC(_mm256)
inline Vector equal(Vector a, Vector b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
inline Vector notEqual(Vector a, Vector b) { return _mm256_cmp_ps(a, b, _CMP_NEQ_UQ); }
inline Vector less(Vector a, Vector b) { return _mm256_cmp_ps(a, b, _CMP_LT_OS); }
inline Vector lessEqual(Vector a, Vector b) { return _mm256_cmp_ps(a, b, _CMP_LE_OS); }
inline Vector greater(Vector a, Vector b) { return _mm256_cmp_ps(a, b, _CMP_GT_OS); }
// Corner c's coordinate `axis` of the lanes: block `low`'s four in lanes 0..3, `high`'s in 4..7.
inline Vector loadCorner(const TriangleBlock& low, const TriangleBlock& high, int c, int axis) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_load_ps(low.corner[c][axis])),
                                _mm_load_ps(high.corner[c][axis]), 1);
}
}  // namespace lane_ops

// The leaf functor over two blocks a test, which the walk below takes for triangle BLASes.
#include "render/bvh/triangle_lanes.inl"
#include "render/bvh/wide_walk_loop.inl"

}  // namespace avx2
}  // namespace pt
