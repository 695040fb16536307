#pragma once
// A 4-wide BVH node for the CPU traversal (issue 21): the boxes of up to four children in
// structure-of-arrays form, so one SSE slab test (render/bvh/wide_walk.h) tests all four.
// Collapsed from the canonical binary tree (render/bvh/wide_bvh.h), which stays the source of
// truth: builders, refits and the GPU keep reading BvhNode. 128 bytes: two cache lines.
#include <cstdint>

namespace pt {

struct alignas(16) WideBvhNode {
    static constexpr uint32_t kWidth = 4;
    static constexpr uint32_t kEmpty = 0xffffffffu;  // count of an unused slot

    float loX[kWidth], loY[kWidth], loZ[kWidth];
    float hiX[kWidth], hiY[kWidth], hiZ[kWidth];
    // Interior child: its node index (into the scene's wide nodes) and count 0. Leaf: its
    // first entry in its BLAS's primitive-index list and its count (1..maxLeafSize). Unused:
    // count kEmpty (children fill the slots from the first).
    uint32_t child[kWidth];
    uint32_t count[kWidth];
};
static_assert(sizeof(WideBvhNode) == 128, "WideBvhNode: 128 bytes");

}  // namespace pt
