#pragma once
// Which instruction set the CPU's 8-wide walk of triangle BLASes runs with (issue 21): chosen
// once, at run time, from what the processor supports, so one binary runs on any x86-64 and
// uses AVX2 where it exists (one 256-bit slab test for a node's eight boxes, where SSE2 takes
// them in two halves). AVX-512 machines take the AVX2 walk: eight slots fill 256 bits. The
// walk behind each level is the same loop (wide_walk_loop.inl) and the same leaf test, so the
// hits do not depend on the level.
#if defined(__CUDACC__)
#error "wide_walk_simd.h is CPU code"
#endif
#include <cstdint>

#include "render/bvh/bvh_walk.h"
#include "render/bvh/hit.h"
#include "render/kernel/triangle_block.h"
#include "render/kernel/wide_bvh_node.h"

namespace pt {

enum class SimdLevel { Sse2, Avx2 };

const char* simdLevelName(SimdLevel level);
// The widest level this processor (and its operating system) runs.
SimdLevel supportedSimdLevel();
// The level the walk uses: supportedSimdLevel() unless set.
SimdLevel wideWalkSimdLevel();
// For tests and benchmarks that compare levels: throws std::invalid_argument for a level the
// processor does not run. Not meant to change while rays are in flight.
void setWideWalkSimdLevel(SimdLevel level);

// Sets the wide walk's level for its lifetime, and restores the one before.
class ScopedSimdLevel {
public:
    explicit ScopedSimdLevel(SimdLevel level) : before_(wideWalkSimdLevel()) { setWideWalkSimdLevel(level); }
    ~ScopedSimdLevel() { setWideWalkSimdLevel(before_); }
    ScopedSimdLevel(const ScopedSimdLevel&) = delete;
    ScopedSimdLevel& operator=(const ScopedSimdLevel&) = delete;

private:
    SimdLevel before_;
};

// walkWideBvh over the 8-wide tree of a triangle BLAS whose leaves index `blocks`, with
// TriangleBlockLeaf, at the chosen level; counts into `stats` where it is not null.
bool walkTriangleWideBvh(const WideBvhNode* nodes, uint32_t root, const TriangleBlock* blocks,
                         const TraversalRay& ray, float& tMax, Hit& hit, TraversalStats* stats, bool anyHit);

namespace simd_detail {
// The walk at each level (wide_walk_simd.cpp, wide_walk_avx2.cpp).
bool walkTriangleWideBvhSse2(const WideBvhNode* nodes, uint32_t root, const TriangleBlock* blocks,
                             const TraversalRay& ray, float& tMax, Hit& hit, TraversalStats* stats,
                             bool anyHit);
bool walkTriangleWideBvhAvx2(const WideBvhNode* nodes, uint32_t root, const TriangleBlock* blocks,
                             const TraversalRay& ray, float& tMax, Hit& hit, TraversalStats* stats,
                             bool anyHit);
// One wide node's slab test at each level, for tests of its bounds: the slots `ray` enters
// before tMax, as a bit mask, and their entry distances.
int intersectWideNodeSse2(const WideBvhNode& node, const TraversalRay& ray, float tMax, float* entry);
int intersectWideNodeAvx2(const WideBvhNode& node, const TraversalRay& ray, float tMax, float* entry);
}  // namespace simd_detail

}  // namespace pt
