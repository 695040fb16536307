#pragma once
// SAH cost of a built BVH (Goldsmith and Salmon 1987; MacDonald and Booth 1990): the expected
// cost of a random ray that hits the root, i.e.
//   (1 / A(root)) * (traversalCost * sum_interior A(n) + intersectionCost * sum_leaves A(l) |l|).
// The root's own traversal counts, so a single-node interior tree costs at least traversalCost.
// The measure the DESIGN uses to compare builders and to decide when refits have degraded a
// BLAS enough to rebuild it.
#include "render/bvh/binned_sah_builder.h"

namespace pt {

// 0 for an empty BVH. When the root box has zero area (all primitives on one line or point)
// areas carry no information and every node counts as if it had the root's area.
float sahCost(const Bvh& bvh, const BvhBuildOptions& options = {});
// The same for a BVH stored elsewhere (a BLAS inside a compiled scene's node array).
float sahCost(const BvhNode* nodes, uint32_t count, const BvhBuildOptions& options = {});

}  // namespace pt
