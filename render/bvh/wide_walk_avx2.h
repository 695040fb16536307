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

#include "render/bvh/lane_ops.h"
#include "render/bvh/triangle_block_intersect.h"
#include "render/bvh/wide_walk.h"

namespace pt {
namespace avx2 {

// The ray as the 256-bit test takes it: per axis, which of a node's two planes the ray meets
// first (its lower one where the inverse direction is positive, else its upper one; the
// inverse is never 0 or NaN, bvh_walk.h), as a byte offset of that plane array in the node, and
// the slab origin that plane is measured from. Each lane then computes the entry and exit
// distances directly, where pt::intersectWideBoxes orders both planes' distances by min and max.
// For any box with lo <= hi the two agree bit for bit on the hit mask and on the entry: the
// subtraction and the multiplication are monotonic, so the ordered distances are the same
// values (their zeros may differ in sign, which the entry's max with +0 and the comparison
// below ignore).
struct WideSlabRay {
    __m256 nearOriginX, nearOriginY, nearOriginZ, farOriginX, farOriginY, farOriginZ, invX, invY, invZ;
    uint32_t nearX, nearY, nearZ, farX, farY, farZ;
};

inline WideSlabRay wideSlabRay(const TraversalRay& ray) {
    constexpr uint32_t kAxisBytes = sizeof(WideBvhNode::loX);
    uint32_t nearPlane[3], farPlane[3];
    float nearOrigin[3], farOrigin[3];
    for (int a = 0; a < 3; ++a) {
        const bool positive = ray.invDirection[a] > 0.0f;
        const uint32_t lo = uint32_t(offsetof(WideBvhNode, loX)) + uint32_t(a) * kAxisBytes;
        const uint32_t hi = uint32_t(offsetof(WideBvhNode, hiX)) + uint32_t(a) * kAxisBytes;
        nearPlane[a] = positive ? lo : hi;
        farPlane[a] = positive ? hi : lo;
        nearOrigin[a] = positive ? ray.slabOriginLo[a] : ray.slabOriginHi[a];
        farOrigin[a] = positive ? ray.slabOriginHi[a] : ray.slabOriginLo[a];
    }
    return {_mm256_set1_ps(nearOrigin[0]),
            _mm256_set1_ps(nearOrigin[1]),
            _mm256_set1_ps(nearOrigin[2]),
            _mm256_set1_ps(farOrigin[0]),
            _mm256_set1_ps(farOrigin[1]),
            _mm256_set1_ps(farOrigin[2]),
            _mm256_set1_ps(ray.invDirection.x),
            _mm256_set1_ps(ray.invDirection.y),
            _mm256_set1_ps(ray.invDirection.z),
            nearPlane[0],
            nearPlane[1],
            nearPlane[2],
            farPlane[0],
            farPlane[1],
            farPlane[2]};
}

// pt::intersectWideBoxes on all eight slots at once, its planes ordered by the ray (above).
inline int intersectWideNode(const WideSlabRay& r, const WideBvhNode& n, float tMax, float* entry) {
    const char* node = reinterpret_cast<const char*>(&n);
    const auto plane = [node](uint32_t offset) {
        return _mm256_load_ps(reinterpret_cast<const float*>(node + offset));
    };
    const __m256 nx = _mm256_mul_ps(_mm256_sub_ps(plane(r.nearX), r.nearOriginX), r.invX);
    const __m256 fx = _mm256_mul_ps(_mm256_sub_ps(plane(r.farX), r.farOriginX), r.invX);
    const __m256 ny = _mm256_mul_ps(_mm256_sub_ps(plane(r.nearY), r.nearOriginY), r.invY);
    const __m256 fy = _mm256_mul_ps(_mm256_sub_ps(plane(r.farY), r.farOriginY), r.invY);
    const __m256 nz = _mm256_mul_ps(_mm256_sub_ps(plane(r.nearZ), r.nearOriginZ), r.invZ);
    const __m256 fz = _mm256_mul_ps(_mm256_sub_ps(plane(r.farZ), r.farOriginZ), r.invZ);
    const __m256 tNear = _mm256_max_ps(_mm256_max_ps(nx, ny), _mm256_max_ps(nz, _mm256_setzero_ps()));
    const __m256 tFar =
        _mm256_mul_ps(_mm256_min_ps(fx, _mm256_min_ps(fy, fz)), _mm256_set1_ps(kSlabExitScale));
    const __m256 limit = _mm256_min_ps(tFar, _mm256_set1_ps(tMax * kSlabExitScale));
    const __m256i unused = _mm256_cmpeq_epi32(_mm256_load_si256(reinterpret_cast<const __m256i*>(n.count)),
                                              _mm256_set1_epi32(int(WideBvhNode::kEmpty)));
    _mm256_store_ps(entry, tNear);
    return _mm256_movemask_ps(
        _mm256_andnot_ps(_mm256_castsi256_ps(unused), _mm256_cmp_ps(tNear, limit, _CMP_LE_OQ)));
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
