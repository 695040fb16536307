#pragma once
// The watertight triangle test (triangle_intersect.h; Woop, Benthin and Wald 2013) on the four
// triangles of a TriangleBlock at once with SSE (issue 21), and the leaf functor of the CPU's
// wide walk over such blocks: triangle_lanes.inl, compiled here with the SSE2 lane operations
// below, and again with AVX2's in wide_walk_avx2.h, where one test takes two blocks.
#if defined(__CUDACC__)
#error "triangle_block_intersect.h is CPU code: CUDA translation units test one triangle at a time"
#endif
#include <emmintrin.h>

#include <cstdint>

#include "render/bvh/bvh_walk.h"
#include "render/bvh/hit.h"
#include "render/bvh/lane_ops.h"
#include "render/kernel/triangle_block.h"

namespace pt {

// triangle_lanes.inl's operations at SSE2: one block a test, four lanes. The comparisons are
// those of the scalar test (ordered; not-equal is true for NaN, as `!=`).
namespace lane_ops {
using Vector = __m128;
constexpr uint32_t kCount = 4;
PT_LANE_ARITHMETIC(_mm)
inline Vector equal(Vector a, Vector b) { return _mm_cmpeq_ps(a, b); }
inline Vector notEqual(Vector a, Vector b) { return _mm_cmpneq_ps(a, b); }
inline Vector less(Vector a, Vector b) { return _mm_cmplt_ps(a, b); }
inline Vector lessEqual(Vector a, Vector b) { return _mm_cmple_ps(a, b); }
inline Vector greater(Vector a, Vector b) { return _mm_cmpgt_ps(a, b); }
// Corner c's coordinate `axis` of the lanes: block `low`'s four (`high` is for two-block tests).
inline Vector loadCorner(const TriangleBlock& low, const TriangleBlock& /*high*/, int c, int axis) {
    return _mm_load_ps(low.corner[c][axis]);
}
}  // namespace lane_ops

#include "render/bvh/triangle_lanes.inl"

// intersectTriangleLanes on one block: the lanes that hit, as a 4-bit mask, with their t, u, v.
inline int intersectTriangleBlock(const WatertightRay& ray, float tMax, const TriangleBlock& block, __m128& t,
                                  __m128& u, __m128& v) {
    return intersectTriangleLanes(ray, tMax, block, block, t, u, v);
}

}  // namespace pt
