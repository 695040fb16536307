// The CPU's 8-wide walk with AVX2 (issue 21; wide_walk_simd.h picks it at run time): a node's
// eight child boxes in one 256-bit slab test (wide_walk_avx2.h). Everything from
// avx2_target_begin.h on is compiled for AVX2, after the shared headers, whose inline functions
// therefore stay SSE2 code in this object as in every other (the linker may keep any one copy of
// them), and the loop copy this file instantiates lives in namespace pt::avx2, a name no SSE2
// code shares.
#include <immintrin.h>

#include <cstddef>
#include <limits>

#include "render/bvh/wide_walk.h"
#include "render/bvh/wide_walk_simd.h"

// clang-format off
#include "render/bvh/avx2_target_begin.h"
#include "render/bvh/wide_walk_avx2.h"
// clang-format on

namespace pt {

bool simd_detail::walkTriangleWideBvhAvx2(const WideBvhNode* nodes, uint32_t root,
                                          const TriangleBlock* blocks, const TraversalRay& ray, float& tMax,
                                          Hit& hit, TraversalStats* stats, bool anyHit) {
    return avx2::walkTriangleBlocks(nodes, root, blocks, ray, tMax, hit, stats, anyHit);
}

int simd_detail::intersectWideNodeAvx2(const WideBvhNode& node, const TraversalRay& ray, float tMax,
                                       float* entry) {
    alignas(32) float entries[WideBvhNode::kWidth];
    const int hits = avx2::intersectWideNode(avx2::wideSlabRay(ray), node, tMax, entries);
    for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) entry[s] = entries[s];
    return hits;
}

}  // namespace pt

#include "render/bvh/avx2_target_end.h"
