#pragma once
// An 8-wide BVH node for the CPU traversal (issue 21): the boxes of up to eight children in
// structure-of-arrays form, so one slab test (render/bvh/wide_walk.h) tests them together.
// Collapsed from the canonical binary tree (render/bvh/wide_bvh.h), which stays the source of
// truth: builders, refits and the GPU keep reading BvhNode. 256 bytes: four cache lines. Eight
// rather than four: on a 1M-triangle sphere (2 threads) 9-17% more rays a second, with the
// same SSE code taking the node in two halves.
#include <cstdint>

namespace pt {

struct alignas(32) WideBvhNode {
    static constexpr uint32_t kWidth = 8;
    static constexpr uint32_t kEmpty = 0xffffffffu;  // count of an unused slot

    float loX[kWidth], loY[kWidth], loZ[kWidth];
    float hiX[kWidth], hiY[kWidth], hiZ[kWidth];
    // Interior child: its node index (into the scene's wide nodes) and count 0. Leaf: its
    // primitive count and, in a triangle BLAS, its first block in the scene's triangle blocks
    // (four triangles a block), in a sphere BLAS its first entry in the BLAS's primitive-index
    // list. Unused: count kEmpty (children fill the slots from the first).
    uint32_t child[kWidth];
    uint32_t count[kWidth];
};
static_assert(sizeof(WideBvhNode) == 256, "WideBvhNode: 256 bytes");

}  // namespace pt
