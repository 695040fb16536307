#pragma once
// What both PLOC builders (ploc_builder.cu: rounds over all clusters; hploc_builder.cu: within
// a warp, up an LBVH) share (device code, nvcc only): a cluster as the node it will become, the
// cost of merging two, the order that breaks ties in cost, and the merge itself.
#include <cuda_runtime.h>

#include <cstdint>

#include "render/backend/cuda/subtree_choices.cuh"
#include "render/bvh/aabb.h"
#include "render/bvh/subtree_collapse.h"
#include "render/kernel/bvh_node.h"

namespace pt::cuda {

// The builders' counters_ words. kStalls: H-PLOC's merge passes that found no mutual pair (a
// defect: each would otherwise loop forever).
enum PlocCounter : uint32_t { kNextSlot, kClustersLeft, kRootHeight, kStalls, kPlocCounters };

// A cluster is the node it will become. A leaf's count is 1 (its height 0); an interior
// cluster's count field holds kInteriorCluster, its subtree choice byte (subtree_choices.cuh)
// at kClusterChoiceShift, and its height (saturated at kClusterHeightMask, far past
// kGpuBvhMaxDepth, beyond which the builders fall back to an LBVH), set to 0 when it is written
// as a node. A count of 0 marks no cluster
// (H-PLOC's slots past a subtree's clusters).
constexpr uint32_t kInteriorCluster = 0x80000000u;
constexpr uint32_t kClusterChoiceShift = 16;
constexpr uint32_t kClusterHeightMask = 0xFFFFu;

__device__ __forceinline__ uint32_t clusterHeight(uint32_t count) {
    return count & kInteriorCluster ? count & kClusterHeightMask : 0u;
}

// A cluster as two 16-byte words: lo and leftOrFirst, hi and count.
struct ClusterWords {
    float4 low, high;
    __device__ uint32_t count() const { return __float_as_uint(high.w); }
    __device__ bool interior() const { return (count() & kInteriorCluster) != 0; }
    __device__ uint32_t height() const { return clusterHeight(count()); }
    // The leaf collapse's byte for the node it will become: a leaf is one primitive, as leaf.
    __device__ uint8_t choice() const {
        return interior() ? uint8_t(count() >> kClusterChoiceShift) : uint8_t(kChoiceLeaf | count());
    }
    __device__ BvhNode asNode() const {
        BvhNode node;
        node.lo = Vec3(low.x, low.y, low.z);
        node.leftOrFirst = __float_as_uint(low.w);
        node.hi = Vec3(high.x, high.y, high.z);
        node.count = interior() ? 0u : count();
        return node;
    }
};

// A cluster an earlier kernel wrote (PLOC's rounds). May come from L1: never for clusters other
// SMs write while this kernel runs (H-PLOC's climb), which take loadClusterCoherent.
__device__ __forceinline__ ClusterWords loadCluster(const BvhNode* clusters, int i) {
    const float4* words = reinterpret_cast<const float4*>(clusters + i);
    return {words[0], words[1]};
}

// The cluster as L2 holds it: another SM may have written it (see bvh_bottom_up.cuh).
__device__ __forceinline__ ClusterWords loadClusterCoherent(const BvhNode* clusters, int i) {
    const float4* words = reinterpret_cast<const float4*>(clusters + i);
    return {__ldcg(words), __ldcg(words + 1)};
}

__device__ __forceinline__ void storeCluster(BvhNode* out, const ClusterWords& c) {
    float4* words = reinterpret_cast<float4*>(out);
    words[0] = c.low;
    words[1] = c.high;
}

// Where merges write: the tree's nodes, and beside them each node's choice byte for the leaf
// collapse with the small subtrees' costs.
struct MergeOutput {
    BvhNode* nodes = nullptr;
    SubtreeChoiceArrays choices;
};

// The cluster written as node `slot`, with its choice byte: an interior cluster's count
// becomes 0.
__device__ __forceinline__ void storeAsNode(const MergeOutput& out, uint32_t slot, ClusterWords c) {
    out.choices.choices[slot] = c.choice();
    if (c.interior()) c.high.w = __uint_as_float(0u);
    storeCluster(out.nodes + slot, c);
}

// Half the surface area of the union of two boxes: PLOC's distance. Symmetric to the bit (min
// and max commute), so both ends of a pair see the same cost.
__device__ __forceinline__ float unionCost(const float4& aLow, const float4& aHigh, const float4& bLow,
                                           const float4& bHigh) {
    const float dx = fmaxf(aHigh.x, bHigh.x) - fminf(aLow.x, bLow.x);
    const float dy = fmaxf(aHigh.y, bHigh.y) - fminf(aLow.y, bLow.y);
    const float dz = fmaxf(aHigh.z, bHigh.z) - fminf(aLow.z, bLow.z);
    const float cost = dx * dy + dy * dz + dz * dx;
    return cost == cost ? cost : INFINITY;  // an infinite box's 0 * inf orders as the largest
}

__device__ __forceinline__ float unionCost(const ClusterWords& a, const ClusterWords& b) {
    return unionCost(a.low, a.high, b.low, b.high);
}

// Where two pairs of clusters cost the same, the one that goes first: the nearer in the order,
// then the one whose lower end is even, then the lower. A total order on pairs that both ends of
// a pair agree on, so the least pair of a round is chosen from both ends and every round merges
// at least once; and where a run of clusters all cost the same (coincident boxes) it pairs them
// off two by two, (0, 1), (2, 3) ..., rather than growing one chain a round.
__device__ __forceinline__ uint64_t tieOrder(int i, int j) {
    const uint32_t gap = uint32_t(i > j ? i - j : j - i), lower = uint32_t(min(i, j));
    return uint64_t(gap) << 33 | uint64_t(lower & 1u) << 32 | lower;
}

// Whether the pair (i, j) at `cost` goes before the pair (i, best) at `bestCost` (best < 0:
// none yet).
__device__ __forceinline__ bool betterNeighbour(int i, int j, float cost, int best, float bestCost) {
    return best < 0 || cost < bestCost || (cost == bestCost && tieOrder(i, j) < tieOrder(i, best));
}

// The optimal cost of a cluster of fewer than kMaxCollapsedLeaf primitives (a merge takes it only
// where its partner adds at least one): a leaf's own, an interior one's as the merge that made
// it stored it. Read from L2: another SM's merge may have
// stored it (see bvh_bottom_up.cuh).
__device__ __forceinline__ float smallClusterCost(const ClusterWords& c, const SubtreeChoiceArrays& out) {
    return c.interior() ? __ldcg(out.pairCosts + pairOf(__float_as_uint(c.low.w))) : leafCost(c.asNode());
}

// The choice byte of `merged`, the union of clusters a and b whose children go to the pair at
// `slot`: one step of the leaf collapse's programme (leafOrSplit, the same arithmetic on the
// same floats as BvhLeafCollapse's own pass, so the bytes agree bit for bit), its cost stored
// where a later merge may still need it.
__device__ __forceinline__ uint8_t mergedChoice(const ClusterWords& a, const ClusterWords& b,
                                                const ClusterWords& merged, uint32_t slot,
                                                const SubtreeChoiceArrays& out) {
    const uint32_t primitives = (a.choice() & kChoicePrimitives) + (b.choice() & kChoicePrimitives);
    if ((a.choice() & kChoicePrimitives) == 0 || (b.choice() & kChoicePrimitives) == 0 ||
        primitives > kMaxCollapsedLeaf) {
        return 0;  // above more than kMaxCollapsedLeaf primitives
    }
    const SubtreeChoice choice = leafOrSplit(nodeSurfaceArea(merged.asNode()), primitives,
                                             smallClusterCost(a, out), smallClusterCost(b, out));
    if (primitives < kMaxCollapsedLeaf) __stcg(out.pairCosts + pairOf(slot), choice.cost);
    return choiceByte(choice);
}

// Writes clusters a and b as nodes into the fresh pair of slots `slot`, `slot` + 1, with their
// choice bytes, and returns the cluster of their union, which points at them.
__device__ __forceinline__ ClusterWords mergeClusters(const ClusterWords& a, const ClusterWords& b,
                                                      const MergeOutput& out, uint32_t slot) {
    storeAsNode(out, slot, a);
    storeAsNode(out, slot + 1, b);
    const uint32_t height = min(max(a.height(), b.height()) + 1u, kClusterHeightMask);
    ClusterWords merged;
    merged.low = make_float4(fminf(a.low.x, b.low.x), fminf(a.low.y, b.low.y), fminf(a.low.z, b.low.z),
                             __uint_as_float(slot));
    merged.high = make_float4(fmaxf(a.high.x, b.high.x), fmaxf(a.high.y, b.high.y), fmaxf(a.high.z, b.high.z),
                              __uint_as_float(kInteriorCluster | height));
    const uint32_t choice = mergedChoice(a, b, merged, slot, out.choices);
    merged.high.w = __uint_as_float(kInteriorCluster | choice << kClusterChoiceShift | height);
    return merged;
}

// The leaf cluster of the primitive at sorted position q (`sortedKey`'s low 32 bits name it),
// and its primIndices entry.
__device__ __forceinline__ ClusterWords leafCluster(const Aabb* boxes, uint64_t sortedKey, uint32_t q,
                                                    uint32_t* primIndices) {
    const uint32_t prim = uint32_t(sortedKey);
    primIndices[q] = prim;
    const Aabb box = boxes[prim];
    return {make_float4(box.lo.x, box.lo.y, box.lo.z, __uint_as_float(q)),
            make_float4(box.hi.x, box.hi.y, box.hi.z, __uint_as_float(1u))};
}

}  // namespace pt::cuda
