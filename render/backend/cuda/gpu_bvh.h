#pragma once
// The CUDA backend's BVH work on the device: building a BLAS or the TLAS from primitive boxes
// (LBVH, or PLOC for BLASes), refitting a BLAS bottom-up after its vertices moved, and measuring SAH cost,
// all in the canonical layout of bvh_node.h, so the shared traversal reads GPU-built and CPU-built trees
// alike. Host functions; every pointer argument is device memory; work is queued on `stream` and nothing here
// synchronises unless it says so.
#include <cuda_runtime.h>

#include <cstdint>

#include "render/backend/cuda/device_buffer.h"
#include "render/backend/cuda/morton_sort.h"
#include "render/bvh/aabb.h"
#include "render/bvh/bvh_walk.h"          // kBvhStackSize
#include "render/bvh/subtree_collapse.h"  // kMaxCollapsedLeaf
#include "render/kernel/bvh_node.h"
#include "render/kernel/render_scene.h"

namespace pt::cuda {

// Node count the LBVH (and PLOC) of `count` primitives writes: 2 count - 1, and 1 (an empty
// root) for 0.
inline uint32_t lbvhNodeCount(uint32_t count) { return count == 0 ? 1u : 2u * count - 1u; }

// The deepest leaf (root at depth 0) of a GPU-built tree: the LBVH's keys bound it, PLOC falls
// back to an LBVH beyond it.
constexpr uint32_t kGpuBvhMaxDepth = 62;
static_assert(kGpuBvhMaxDepth < kBvhStackSize, "the traversal stack must hold a GPU-built tree's path");

// Linear BVH (Karras, "Maximizing Parallelism in the Construction of BVHs, Octrees, and k-d
// Trees", HPG 2012): 30-bit Morton codes of box centres in the boxes' common bounds, a radix
// sort, one thread per internal node to find its range and split, boxes bottom-up. One
// primitive per leaf. Keeps its scratch memory between builds.
// Layout: the root (Karras internal node 0) is node 0 and the two children of Karras internal
// node i are nodes 1 + 2i and 2 + 2i, so siblings are adjacent without a renumbering pass; the
// leaf of the primitive at sorted position q has leftOrFirst = q. Keys are Morton code << 32 |
// primitive index, unique even where centres coincide, so the depth is bounded by the key bits.
// The scratch is the builder's: one build at a time per builder (builds that may overlap on
// different streams need a builder each).
class LbvhBuilder {
public:
    // Writes lbvhNodeCount(count) nodes to `nodes` (root first; siblings adjacent) and `count`
    // entries to `primIndices` (indices into `boxes`). `boxes` must hold no NaN. The result
    // obeys every rule of binned_sah_builder.h's Bvh except the leaf size (always 1) and
    // depth-first order; its depth is at most kGpuBvhMaxDepth. `nodes` must be 16-byte aligned,
    // as every cudaMalloc'd array is.
    void build(const Aabb* boxes, uint32_t count, BvhNode* nodes, uint32_t* primIndices, cudaStream_t stream);
    // The same from the boxes' keys as MortonSort::sort gives them (count >= 2), where another
    // builder has sorted them already.
    void buildFromSortedKeys(const Aabb* boxes, const uint64_t* sortedKeys, uint32_t count, BvhNode* nodes,
                             uint32_t* primIndices, cudaStream_t stream);
    // The LBVH works out no leaf-collapse choices (see PlocBuilder::subtreeChoices): its boxes
    // are computed bottom-up after the topology, where BvhLeafCollapse's own pass does as well.
    const uint8_t* subtreeChoices() const { return nullptr; }
    // Frees the scratch (the next build allocates it again): once the trees it built for a first
    // frame have been replaced, at 10M triangles it would hold about 400 MiB for nothing.
    void release();
    // Device memory the scratch holds (it grows with the largest build so far).
    uint64_t bytes() const {
        return morton_.bytes() + leafSlots_.bytes() + internalSlots_.bytes() + visits_.bytes();
    }

private:
    // Grows the scratch to `count` primitives: builds of the same size or smaller reuse it.
    void reserve(uint32_t count);

    uint32_t capacity_ = 0;
    MortonSort morton_;
    DeviceBuffer<uint32_t> leafSlots_;      // node index of the leaf of each sorted primitive
    DeviceBuffer<uint32_t> internalSlots_;  // node index of each Karras internal node
    DeviceBuffer<uint32_t> visits_;         // bottom-up box pass: arrivals per node
};

// Parallel Locally-Ordered Clustering (Meister and Bittner, "Parallel Locally-Ordered Clustering
// for Bounding Volume Hierarchy Construction", IEEE TVCG 2018): a bottom-up build that merges
// clusters in Morton order, each with the one among its kPlocRadius neighbours on either side
// whose union has the least surface area, wherever the choice is mutual, until one is left.
// Agglomerative clustering by surface area is what a SAH top-down build approximates from the
// other end: on an H200, PLOC's trees cost 1.03-1.15x the binned SAH build's where the LBVH's
// Morton splits cost 1.09-1.21x (gpu_bvh_test.cpp and pt-render bench measure both).
constexpr int kPlocRadius = 16;

// The same contract as LbvhBuilder::build (one primitive a leaf, siblings adjacent, root at 0,
// lbvhNodeCount(count) nodes, `nodes` 16-byte aligned), except that leaves are not in Morton
// order and the build synchronises `stream`: it reads the cluster count back every few rounds.
// PLOC bounds no depth: a tree deeper than kGpuBvhMaxDepth is replaced by an LBVH of the same
// boxes, and lastBuildFellBack() says so.
class PlocBuilder {
public:
    void build(const Aabb* boxes, uint32_t count, BvhNode* nodes, uint32_t* primIndices, cudaStream_t stream);
    // Whether the last build's tree was too deep and an LBVH took its place.
    bool lastBuildFellBack() const { return fellBack_; }
    // The depth of the last build's tree as PLOC made it (deeper than kGpuBvhMaxDepth where it
    // fell back, saturated at 65535; 0 for fewer than two primitives).
    uint32_t lastBuildDepth() const { return depth_; }
    // The last build's choice byte for every node (subtree_choices.cuh), worked out as its merges
    // made the nodes, for BvhLeafCollapse::collapse to take in place of its own pass; device
    // memory, written on the build's stream, and true of the tree until the next build or until
    // a collapse rewrites it. nullptr where the build made no merges (fewer than two primitives)
    // or fell back.
    const uint8_t* subtreeChoices() const { return choicesValid_ ? choices_.data() : nullptr; }
    // Frees the scratch, as LbvhBuilder::release.
    void release();
    uint64_t bytes() const {
        return morton_.bytes() + clusters_.bytes() + merged_.bytes() + keep_.bytes() +
               selectScratch_.bytes() + counters_.bytes() + choices_.bytes() + pairCosts_.bytes() +
               fallback_.bytes();
    }

private:
    // Grows the scratch to `count` primitives: builds of the same size or smaller reuse it.
    void reserve(uint32_t count);

    uint32_t capacity_ = 0;
    bool fellBack_ = false;
    uint32_t depth_ = 0;
    MortonSort morton_;
    // The clusters of a round in Morton order, each as the node it will become (ploc_clusters.cuh
    // says what an interior cluster's count field carries), and the round's clusters
    // after merging, before the merged-away ones are compacted out.
    DeviceBuffer<BvhNode> clusters_, merged_;
    DeviceBuffer<uint8_t> keep_;  // 1: the cluster goes on to the next round
    DeviceBuffer<uint8_t> selectScratch_;
    DeviceBuffer<uint32_t> counters_;  // PlocCounter: the next free node slot, clusters left, root height
    // The merges' choice bytes (a node each) and small subtrees' costs (a sibling pair each).
    DeviceBuffer<uint8_t> choices_;
    DeviceBuffer<float> pairCosts_;
    bool choicesValid_ = false;
    LbvhBuilder fallback_;
};

// H-PLOC (Benthin et al., "H-PLOC: Hierarchical Parallel Locally-Ordered Clustering for
// Bounding Volume Hierarchy Construction", HPG 2024): PLOC's clustering done inside the LBVH's
// hierarchy, in one kernel. Threads climb the LBVH from its leaves (Apetrei, "Fast and Simple
// Agglomerative LBVH Construction", CGVC 2014: the second child to arrive goes on); where a node spans
// more than kHplocThreshold primitives, its warp merges the clusters its two children kept, by
// PLOC with kHplocRadius, until kHplocThreshold are left (the root: one). No rounds over the
// whole set, so no read-backs and one launch. The same contract as PlocBuilder; its fallback
// LBVH reuses the sorted keys. build throws std::logic_error where the merges did not hand out
// exactly the 2n - 2 slots below the root: a defect of the builder, never of the input.
// The CUDA backend's GPU builds (IntegratorToggles::gpuPloc). On an H200, 1M boxes (gpu_bvh_test's
// speed test) in 0.80 ms at 1.051x the binned SAH cost, where PLOC's rounds take 1.83 ms at
// 1.048x; pt-render bench's 1M sphere 0.70 ms at 1.126x (PLOC 1.36 ms at 1.139x), its 10M
// sphere 4.5 ms at 1.142x (PLOC 6.1 ms at 1.148x). The radius trades time for little: 4, 6, 8,
// 12, 16 took 0.57, 0.67, 0.80, 1.10, 1.38 ms at 1.056, 1.053, 1.051, 1.050, 1.049x, and a
// larger radius only near the root was slower and worse.
constexpr int kHplocThreshold = 16;
constexpr int kHplocRadius = 8;

class HplocBuilder {
public:
    void build(const Aabb* boxes, uint32_t count, BvhNode* nodes, uint32_t* primIndices, cudaStream_t stream);
    bool lastBuildFellBack() const { return fellBack_; }
    uint32_t lastBuildDepth() const { return depth_; }
    const uint8_t* subtreeChoices() const { return choicesValid_ ? choices_.data() : nullptr; }
    void release();
    uint64_t bytes() const {
        return morton_.bytes() + clusters_.bytes() + siblingBounds_.bytes() + counters_.bytes() +
               choices_.bytes() + pairCosts_.bytes() + fallback_.bytes();
    }

private:
    void reserve(uint32_t count);

    uint32_t capacity_ = 0;
    bool fellBack_ = false;
    uint32_t depth_ = 0;
    MortonSort morton_;
    // At each sorted position, the cluster of that leaf, until a subtree's merge writes its
    // clusters over the first positions of its range and marks the rest empty.
    DeviceBuffer<BvhNode> clusters_;
    // Per LBVH split (between sorted keys i and i + 1): the far end of the range of the child that
    // arrived first, ~0u until then.
    DeviceBuffer<uint32_t> siblingBounds_;
    DeviceBuffer<uint32_t> counters_;  // PlocCounter: slots taken after the root's, -, root height
    DeviceBuffer<uint8_t> choices_;    // as PlocBuilder's
    DeviceBuffer<float> pairCosts_;
    bool choicesValid_ = false;
    LbvhBuilder fallback_;  // from the same sorted keys
};

// The SAH leaf rule of a top-down build (render/bvh/subtree_collapse.h) applied to a tree the
// builders above made: every subtree of at most kMaxCollapsedLeaf primitives whose optimal SAH
// cost is as one leaf becomes that leaf, and the nodes below it go. On an H200 it takes H-PLOC's
// trees of pt-render bench's 1M sphere from 1.119x to 1.085x the binned SAH build's cost (1.048x
// to 1.036x on 100k random triangles, 1.040x to 0.992x clustered, 1.091x to 1.070x on an 82k
// icosphere: gpu_bvh_test), for 0.35-0.43 ms more at 1M primitives with its own choices' pass,
// 0.11-0.13 ms with H-PLOC's (bench's 1M sphere: H-PLOC and the collapse 0.82-0.84 ms); of 1M
// random triangles' tree it keeps 62% of the nodes. The backend's builders build into the
// collapse's scratch (buildScratch) and the collapse writes the kept tree to the BLAS's place
// (collapseInto), so no copy follows it. Keeps its scratch between collapses, as the builders
// do: about 45 bytes a node of the input (0.9 GB at 10M primitives) until release().
class BvhLeafCollapse {
public:
    // Room for a tree of `nodeCount` nodes over `primCount` primitive indices, for a builder
    // to build into and collapseInto to read: valid until the next buildScratch, collapse or
    // release.
    struct BuildScratch {
        BvhNode* nodes;
        uint32_t* primIndices;
    };
    BuildScratch buildScratch(uint32_t nodeCount, uint32_t primCount);

    // `builtNodes` holds `nodeCount` nodes in the builders' layout (root at 0; the children of
    // every interior node at slots 2p + 1 and 2p + 2), over `primCount` entries of
    // `builtPrimIndices`; both are left as they are. Writes the collapsed tree to `nodes` and
    // `primIndices` (room for nodeCount and primCount entries, apart from the input), in that
    // layout, with the kept nodes in their order and each leaf's primitives in their order below
    // it, and returns the new node count. The result obeys every rule of the builders' trees but
    // the leaf size, which is at most kMaxCollapsedLeaf (a leaf of more primitives is kept as it
    // is), and its depth does not grow. Waits for `stream` once, at the end (it reads the kept
    // count back); throws std::logic_error where the primitives placed do not add up (a tree not
    // in that layout: never one of the builders'), or where nodeCount is even.
    // `builtChoices`, where the builder that made the tree gives them (subtreeChoices()), stand
    // in for the choices' own pass (parent links and a climb from every leaf), with the same
    // result.
    uint32_t collapseInto(const BvhNode* builtNodes, uint32_t nodeCount, const uint32_t* builtPrimIndices,
                          uint32_t primCount, BvhNode* nodes, uint32_t* primIndices, cudaStream_t stream,
                          const uint8_t* builtChoices = nullptr);
    // The same in place: `nodes` and `primIndices` are copied to the build scratch first.
    uint32_t collapse(BvhNode* nodes, uint32_t nodeCount, uint32_t* primIndices, uint32_t primCount,
                      cudaStream_t stream, const uint8_t* builtChoices = nullptr);
    void release();
    uint64_t bytes() const {
        return choices_.bytes() + parentsThenPairKept_.bytes() + visitsThenPairStarts_.bytes() +
               costsThenLeafPrimitives_.bytes() + builtNodes_.bytes() + builtPrimIndices_.bytes() +
               scanScratch_.bytes();
    }

private:
    void reserve(uint32_t nodeCount, uint32_t primCount);
    // Pass 1 (bvh_leaf_collapse.cu): every node's choice into choices_.
    void choose(const BvhNode* nodes, uint32_t nodeCount, cudaStream_t stream);

    uint32_t nodeCapacity_ = 0, primCapacity_ = 0;
    // Per node: the primitives below it (up to the limit) and whether it is to be a leaf.
    DeviceBuffer<uint8_t> choices_;
    // Each for the choices' pass and then for the marks (bvh_leaf_collapse.cu): parent links,
    // then 1 where a sibling pair stays (a word a node); arrivals (a word a node), then a word
    // pair a pair, the scan of the pairs kept and the primitives placed before it; optimal
    // costs, then each kept leaf's primitives (a word a node).
    DeviceBuffer<uint32_t> parentsThenPairKept_;
    DeviceBuffer<uint64_t> visitsThenPairStarts_;
    DeviceBuffer<uint32_t> costsThenLeafPrimitives_;
    DeviceBuffer<BvhNode> builtNodes_;  // buildScratch
    DeviceBuffer<uint32_t> builtPrimIndices_;
    DeviceBuffer<uint8_t> scanScratch_;
};

// The object-space box of each primitive of `blas` (mesh-local order), read from the device
// geometry `scene` points at.
void computePrimitiveBoxes(const RenderScene& scene, const BlasRef& blas, Aabb* boxes, cudaStream_t stream);

// parents[i] = the node whose children include node i; parents[0] = ~0u.
void computeParents(const BvhNode* nodes, uint32_t nodeCount, uint32_t* parents, cudaStream_t stream);

// Bottom-up refit: every node's box becomes the exact union of its primitives' current boxes
// (`primBoxes`, indexed like the BVH's primIndices entries); the topology is kept. `parents`
// comes from computeParents over the same topology; `visits` is nodeCount words of scratch.
// `nodes` must be 16-byte aligned (boxes are read as float4), as every cudaMalloc'd node is.
void refitBvh(BvhNode* nodes, uint32_t nodeCount, const uint32_t* parents, const uint32_t* primIndices,
              const Aabb* primBoxes, uint32_t* visits, cudaStream_t stream);

// After refitBvh of a BLAS: its `count` compressed 8-wide nodes requantised from the binary
// nodes `binary` their slots came from (`sourceNodes`, 8 per node, relative to `binary`).
void requantizeCompressedNodes(CompressedWideNode* nodes, uint32_t count, const BvhNode* binary,
                               const uint32_t* sourceNodes, cudaStream_t stream);
// And its `count` compressed leaf triangles `out` from the primitives `prims` (parallel to
// them), corners from `positions`.
void gatherLeafTriangles(LeafTriangle* out, const uint32_t* prims, uint32_t count,
                         const TriangleIndices* triangles, const Vec3* positions, const BlasRef& blas,
                         cudaStream_t stream);

// SAH cost as sah_cost.h defines it (traversal and intersection cost 1), equal to the host's
// sahCost() of the same nodes to float rounding. Synchronises `stream`.
float sahCostOnDevice(const BvhNode* nodes, uint32_t nodeCount, cudaStream_t stream);

// World-space box of each instance: its BLAS root box through objectToWorld, padded exactly as
// the CPU scene compiler pads it (render/bvh/instance_bounds.h).
void computeInstanceBoxes(const RenderInstance* instances, uint32_t count, const BlasRef* blases,
                          const BvhNode* blasNodes, Aabb* boxes, cudaStream_t stream);

}  // namespace pt::cuda
