#pragma once
// Collapsing a binary BVH into an 8-wide one (issue 21) for the CPU traversal: each wide node
// takes a binary node's children and keeps opening the largest interior one (by surface area,
// the child a ray is likeliest to enter) until it holds eight, as Embree's BVH8 and Wald et al.
// 2008 ("Getting Rid of Packets", the multi-branching BVH) collapse a binary SAH tree. Leaves
// keep their primitive ranges, so the wide walk tests the primitives the binary walk would;
// optionally a binary subtree of few primitives becomes one wide leaf (their range), as
// Embree's leaves of four triangles tested together (triangle_block.h) are: a SIMD test of four
// costs about what one costs, and its boxes cull less than they cost. Each wide slot remembers
// its binary node, so a refit of the binary tree refreshes the wide boxes in one pass
// (refreshWideBoxes) instead of collapsing again.
#include <cstdint>
#include <vector>

#include "render/kernel/bvh_node.h"
#include "render/kernel/wide_bvh_node.h"

namespace pt {

struct WideBvh {
    std::vector<WideBvhNode> nodes;     // nodes[0] is the root
    std::vector<uint32_t> sourceNodes;  // per slot (node * 4 + slot): its binary node, or kEmpty
};

// The up to eight binary nodes one wide node holds: openLargestChildren's greedy choice in the
// CPU's 8-wide collapse, SahCollapse::childrenOf's in the compressed GPU tree (sah_collapse.h
// says why the CPU keeps the greedy one). Held in place: collapses make one per wide node,
// hundreds of thousands of times.
struct WideChildren {
    static constexpr uint32_t kMaxWidth = 8;
    uint32_t node[kMaxWidth];
    uint32_t count = 0;

    uint32_t size() const { return count; }
    uint32_t operator[](uint32_t i) const { return node[i]; }
};
// Those under binary interior node `binary`: its two children, the largest interior one (by
// surface area) opened while there is room for `width`. With `leafCounts` (per binary node:
// its primitives where the wide tree makes it a leaf, else 0), nodes it makes leaves are never
// opened; without, the binary leaves alone.
WideChildren openLargestChildren(const BvhNode* nodes, uint32_t binary, uint32_t width,
                                 const uint32_t* leafCounts = nullptr);

// The wide form of the binary tree `nodes` (canonical layout, root at 0, `count` nodes); child
// node indices count from the result's first node. An empty tree (a root without primitives)
// gives one node with no used slot. With `leafPrimitives` > 0, an interior binary node whose
// subtree holds at most that many primitives, in one contiguous range of the primitive list
// (as the binned builder lays them out), becomes one leaf over that range; with 0 the wide
// leaves are the binary ones.
WideBvh collapseToWide(const BvhNode* nodes, uint32_t count, uint32_t leafPrimitives = 0);

// Copies the boxes of the binary nodes the slots came from (after a refit of `binary`).
void refreshWideBoxes(const BvhNode* binary, const uint32_t* sourceNodes, WideBvhNode* wide,
                      uint32_t wideCount);

}  // namespace pt
