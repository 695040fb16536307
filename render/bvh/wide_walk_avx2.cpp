// The CPU's 8-wide walk with AVX2 (issue 21; wide_walk_simd.h picks it at run time): a node's
// eight child boxes in one 256-bit slab test. Everything here is compiled for AVX2 by the target
// pragma below, after the shared headers, whose inline functions therefore stay SSE2 code in
// this object as in every other (the linker may keep any one copy of them), and the loop copy
// this file instantiates lives in namespace pt::avx2, a name no SSE2 code shares. Each lane
// computes what the SSE2 test computes for that slot, so the walk visits the same nodes.
#include <immintrin.h>

#include "render/bvh/wide_walk.h"
#include "render/bvh/wide_walk_simd.h"

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif

namespace pt {
namespace avx2 {

struct WideSlabRay {
    __m256 oLoX, oLoY, oLoZ, oHiX, oHiY, oHiZ, invX, invY, invZ;
};

inline WideSlabRay wideSlabRay(const TraversalRay& ray) {
    return {_mm256_set1_ps(ray.slabOriginLo.x), _mm256_set1_ps(ray.slabOriginLo.y),
            _mm256_set1_ps(ray.slabOriginLo.z), _mm256_set1_ps(ray.slabOriginHi.x),
            _mm256_set1_ps(ray.slabOriginHi.y), _mm256_set1_ps(ray.slabOriginHi.z),
            _mm256_set1_ps(ray.invDirection.x), _mm256_set1_ps(ray.invDirection.y),
            _mm256_set1_ps(ray.invDirection.z)};
}

// pt::intersectWideBoxes on all eight slots at once (same operations, same operand order).
inline int intersectWideNode(const WideSlabRay& r, const WideBvhNode& n, float tMax, float* entry) {
    const __m256 x0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.loX), r.oLoX), r.invX);
    const __m256 x1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.hiX), r.oHiX), r.invX);
    const __m256 y0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.loY), r.oLoY), r.invY);
    const __m256 y1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.hiY), r.oHiY), r.invY);
    const __m256 z0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.loZ), r.oLoZ), r.invZ);
    const __m256 z1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.hiZ), r.oHiZ), r.invZ);
    const __m256 tNear = _mm256_max_ps(_mm256_max_ps(_mm256_min_ps(x0, x1), _mm256_min_ps(y0, y1)),
                                       _mm256_max_ps(_mm256_min_ps(z0, z1), _mm256_setzero_ps()));
    const __m256 tFar = _mm256_mul_ps(
        _mm256_min_ps(_mm256_max_ps(x0, x1), _mm256_min_ps(_mm256_max_ps(y0, y1), _mm256_max_ps(z0, z1))),
        _mm256_set1_ps(kSlabExitScale));
    const __m256 limit = _mm256_min_ps(tFar, _mm256_set1_ps(tMax * kSlabExitScale));
    const __m256i unused = _mm256_cmpeq_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(n.count)),
                                              _mm256_set1_epi32(int(WideBvhNode::kEmpty)));
    _mm256_store_ps(entry, tNear);
    return _mm256_movemask_ps(
        _mm256_andnot_ps(_mm256_castsi256_ps(unused), _mm256_cmp_ps(tNear, limit, _CMP_LE_OQ)));
}

#include "render/bvh/wide_walk_loop.inl"

}  // namespace avx2

bool simd_detail::walkTriangleWideBvhAvx2(const WideBvhNode* nodes, uint32_t root,
                                          const TriangleBlock* blocks, const TraversalRay& ray, float& tMax,
                                          Hit& hit, TraversalStats* stats, bool anyHit) {
    return avx2::walkTriangleBlocks(nodes, root, blocks, ray, tMax, hit, stats, anyHit);
}

}  // namespace pt

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
