#pragma once
// Binned SAH BVH builder (host): Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", IEEE Symposium on Interactive Ray Tracing 2007. Primitive centroids are binned
// along all three axes, the split plane minimising the surface area heuristic (Goldsmith and
// Salmon 1987; MacDonald and Booth 1990) is taken among the bin boundaries, and the recursion
// runs as TBB tasks over disjoint primitive ranges. Used for every BLAS (object-space primitive
// boxes) and for the TLAS (world-space instance boxes).
#include <cstdint>
#include <functional>
#include <vector>

#include "render/bvh/aabb.h"
#include "render/kernel/bvh_node.h"

namespace pt {

struct BvhBuildOptions {
    uint32_t binCount = 16;         // per axis; clamped to [2, 64]
    uint32_t maxLeafSize = 4;       // every leaf holds 1..maxLeafSize primitives
    float traversalCost = 1.0f;     // SAH cost of visiting an interior node
    float intersectionCost = 1.0f;  // SAH cost of one primitive test
    // Called with a leaf's primitive count as each leaf is made, from any builder thread:
    // the hook for progress reports on big builds. May be empty.
    std::function<void(uint32_t)> onLeaf;
};

// Canonical layout (bvh_node.h). nodes[0] is the root; child indices are into `nodes`, leaf
// ranges into `primIndices`, whose entries are indices into the builder's input.
//  - count == 0: a single root node with an empty box (lo = +inf, hi = -inf) and count 0,
//    and no primitive indices. Every ray misses the empty box, so traversal never reads the
//    children its count of 0 would otherwise announce.
//  - otherwise every input primitive appears in exactly one leaf, every leaf holds
//    1..maxLeafSize primitives, a node's box is the exact union of its primitives' boxes, and
//    no leaf is deeper than kBvhStackSize (bvh_walk.h), the traversal stack.
// Nodes are stored depth first (left subtree before right); the output does not depend on
// thread scheduling.
struct Bvh {
    std::vector<BvhNode> nodes;
    std::vector<uint32_t> primIndices;
};

// primBounds[i] is the box of primitive i; boxes must not contain NaN. Degenerate input
// (coincident centroids, zero-area boxes) is split by count so the build always terminates.
Bvh buildBinnedSahBvh(const Aabb* primBounds, uint32_t count, const BvhBuildOptions& options = {});

}  // namespace pt
