// BvhLeafCollapse (gpu_bvh.h): the SAH leaf rule of render/bvh/subtree_collapse.h over a tree
// the GPU builders made, then the tree compacted into the same layout. Passes, all queued on the
// caller's stream:
//   1. parent links (computeParents), then each node's choice bottom-up: a thread a leaf climbs
//      while the subtree below stays within kMaxCollapsedLeaf primitives (the second child's
//      thread to arrive goes on, as in the refit: bvh_bottom_up.cuh), recording how many
//      primitives lie below each node it reaches, its optimal cost, and whether that is as one
//      leaf. A node it does not reach has more primitives below (its choice stays 0). Where
//      the PLOC builders made the tree they give these bytes, worked out as they merged
//      (subtree_choices.cuh), and this pass is left out;
//   2. which sibling pairs stay and which nodes become leaves: a node above more than
//      kMaxCollapsedLeaf primitives always stays, so its thread walks down its small children's
//      subtrees (at most 7 nodes each) and marks what the choices keep; every mark is written
//      by one thread;
//   3. one exclusive scan of a word pair a sibling pair, the pair's mark and its leaves'
//      primitives, gives each kept pair its new slot and each leaf its place in the primitive
//      list (cub::DeviceScan), and in a last word past the pairs the totals;
//   4. each kept node writes itself at its new slot of the output, a leaf gathering the
//      primitives below it. The backend's builders build into this object's scratch, so the
//      output is the BLAS's own place and nothing is copied after (collapseInto); the totals
//      are read back at the end, so the GPU does not wait for the host between passes.
// The first pass's buffers (parents, arrivals, costs) hold the second's marks once it is done.
// On an H200 (1M random triangles, ncu) the choices' pass takes 188 us, held up by the latency
// of its atomics and fences (118 cycles an issued instruction). Two trials of it were slower: a
// thread a node walking down with collapseChoice, depth first, 206 us; the same opening both
// children together with a lower bound that gives up early, 436 us (its arrays in local memory).
// Then mark 48 us, write 81 us (40 registers, 75% occupancy), parents 28 us.
#include <thrust/iterator/counting_iterator.h>
#include <thrust/iterator/transform_iterator.h>

#include <algorithm>
#include <cub/device/device_scan.cuh>
#include <stdexcept>
#include <string>

#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/backend/cuda/subtree_choices.cuh"
#include "render/bvh/subtree_collapse.h"

namespace pt::cuda {

namespace {

// Thread per node; the leaves' threads climb. `choices` zeroed, `visits` zeroed.
__global__ void chooseKernel(const BvhNode* nodes, uint32_t nodeCount, const uint32_t* parents,
                             uint32_t* visits, uint8_t* choices, float* costs) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= nodeCount) return;
    const BvhNode leaf = nodes[i];
    if (!leaf.isLeaf()) return;
    if (leaf.count > kMaxCollapsedLeaf) {  // stays as it is; its parent is above more too
        choices[i] = kChoiceLeaf;
        return;
    }
    __stcg(costs + i, leafCost(leaf));
    __stcg(choices + i, uint8_t(kChoiceLeaf | leaf.count));
    climbAsSecondArrival(
        i, visits, [&](uint32_t node) { return parents[node]; },
        [&](uint32_t parent) {
            const BvhNode above = nodes[parent];  // boxes and topology: not written by this pass
            const uint32_t left = above.leftOrFirst;
            // L2's copies: L1 is not coherent across SMs.
            const uint32_t primitives = (__ldcg(choices + left) & kChoicePrimitives) +
                                        (__ldcg(choices + left + 1) & kChoicePrimitives);
            // Both children arrived, so both are small; together they may not be.
            if (primitives > kMaxCollapsedLeaf) return false;
            const SubtreeChoice choice = leafOrSplit(nodeSurfaceArea(above), primitives, __ldcg(costs + left),
                                                     __ldcg(costs + left + 1));
            __stcg(costs + parent, choice.cost);
            __stcg(choices + parent, choiceByte(choice));
            return true;
        });
}

// Marks what stays of the subtree under `top`, a kept node of at most kMaxCollapsedLeaf
// primitives: down to the first node on each path whose choice is a leaf.
__device__ void markSmallSubtree(const BvhNode* nodes, const uint8_t* choices, uint32_t top,
                                 uint32_t* pairKept, uint32_t* leafPrimitives) {
    uint32_t stack[kMaxCollapsedLeaf];
    uint32_t depth = 0;
    stack[depth++] = top;
    while (depth > 0) {
        const uint32_t index = stack[--depth];
        const uint8_t choice = choices[index];
        if (choice & kChoiceLeaf) {
            leafPrimitives[index] = choice & kChoicePrimitives;
            continue;
        }
        const uint32_t left = nodes[index].leftOrFirst;
        pairKept[pairOf(left)] = 1;
        if (depth + 2 > kMaxCollapsedLeaf) continue;  // unreachable below a small subtree's root
        stack[depth++] = left + 1;
        stack[depth++] = left;
    }
}

__global__ void markKernel(const BvhNode* nodes, uint32_t nodeCount, const uint8_t* choices,
                           uint32_t* pairKept, uint32_t* leafPrimitives) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= nodeCount) return;
    const bool small = (choices[i] & kChoicePrimitives) != 0;
    if (small) {
        // Marked by the thread of its nearest large ancestor, unless it is the root.
        if (i == 0) markSmallSubtree(nodes, choices, 0, pairKept, leafPrimitives);
        return;
    }
    const BvhNode node = nodes[i];
    if (node.isLeaf()) {  // more than kMaxCollapsedLeaf primitives: it stays as it is
        leafPrimitives[i] = node.count;
        return;
    }
    pairKept[pairOf(node.leftOrFirst)] = 1;
    for (uint32_t child = node.leftOrFirst; child < node.leftOrFirst + 2; ++child) {
        if (choices[child] & kChoicePrimitives)
            markSmallSubtree(nodes, choices, child, pairKept, leafPrimitives);
    }
}

// The scan's input: for sibling pair p, 1 << 32 where it stays plus the primitives of its kept
// leaves (all of them together are primCount < 2^32, so the low word never carries into the
// high), and for pair 0 the root's too, where the root is the one leaf (then no pair stays, and
// its own offset is 0). Past the last pair a 0, whose exclusive scan is then the totals: the
// pairs kept and the primitives placed.
struct PairWord {
    const uint32_t* pairKept;
    const uint32_t* leafPrimitives;
    uint32_t pairs;
    __device__ uint64_t operator()(uint32_t p) const {
        if (p == pairs) return 0;
        const uint32_t root = p == 0 ? leafPrimitives[0] : 0u;
        return uint64_t(pairKept[p]) << 32 | (root + leafPrimitives[2 * p + 1] + leafPrimitives[2 * p + 2]);
    }
};

// `pairStarts[p]`, the exclusive scan of PairWord: the pairs kept before pair p (high word) and
// the primitives of the kept leaves before its own (low word).
__global__ void writeKernel(const BvhNode* nodes, uint32_t nodeCount, const uint32_t* primIndices,
                            uint32_t primCount, const uint8_t* choices, const uint32_t* pairKept,
                            const uint32_t* leafPrimitives, const uint64_t* pairStarts, BvhNode* outNodes,
                            uint32_t* outPrimIndices) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= nodeCount) return;
    if (i != 0 && !pairKept[pairOf(i)]) return;
    uint32_t slot = 0, next = 0;  // the root: slot 0, and its primitives first where it is a leaf
    if (i != 0) {
        const uint64_t start = pairStarts[pairOf(i)];
        const bool right = (i - 1) & 1u;
        slot = 1 + 2 * uint32_t(start >> 32) + uint32_t(right);
        next = uint32_t(start) + (right ? leafPrimitives[i - 1] : 0u);  // after its left sibling's
    }
    BvhNode out = nodes[i];
    if (choices[i] & kChoiceLeaf) {  // its primitives, in their order below it, from its offset on
        out.leftOrFirst = next;
        forEachSmallSubtreeLeaf(nodes, i, [&](const BvhNode& leaf) {
            for (uint32_t k = 0; k < leaf.count; ++k, ++next) {
                // Never past the output, even for a tree whose totals the host then refuses.
                if (next < primCount) outPrimIndices[next] = primIndices[leaf.leftOrFirst + k];
            }
        });
        out.count = next - out.leftOrFirst;
    } else {
        out.leftOrFirst = 1 + 2 * uint32_t(pairStarts[pairOf(out.leftOrFirst)] >> 32);
    }
    outNodes[slot] = out;
}

// The scan's input iterator (PairWord over pair indices 0..pairs).
auto pairWords(const uint32_t* pairKept, const uint32_t* leafPrimitives, uint32_t pairs) {
    return thrust::make_transform_iterator(thrust::make_counting_iterator(0u),
                                           PairWord{pairKept, leafPrimitives, pairs});
}

}  // namespace

void BvhLeafCollapse::reserve(uint32_t nodeCount, uint32_t primCount) {
    if (nodeCount > nodeCapacity_) {
        nodeCapacity_ = grownCapacity(nodeCount, nodeCapacity_);
        choices_.resize(nodeCapacity_);
        parentsThenPairKept_.resize(nodeCapacity_);
        // A word a node (arrivals), or a word pair for each pair and one past them.
        visitsThenPairStarts_.resize(nodeCapacity_ / 2 + 1);
        costsThenLeafPrimitives_.resize(nodeCapacity_);
        builtNodes_.resize(nodeCapacity_);
        size_t scanBytes = 0;
        PT_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(nullptr, scanBytes, pairWords(nullptr, nullptr, 0),
                                                    visitsThenPairStarts_.data(),
                                                    int(nodeCapacity_ / 2 + 1)));
        scanScratch_.resize(std::max<size_t>(scanBytes, 1));
    }
    if (primCount > primCapacity_) {
        primCapacity_ = grownCapacity(primCount, primCapacity_);
        builtPrimIndices_.resize(primCapacity_);
    }
}

void BvhLeafCollapse::release() {
    choices_ = {};
    parentsThenPairKept_ = {};
    visitsThenPairStarts_ = {};
    costsThenLeafPrimitives_ = {};
    builtNodes_ = {};
    builtPrimIndices_ = {};
    scanScratch_ = {};
    nodeCapacity_ = 0;
    primCapacity_ = 0;
}

BvhLeafCollapse::BuildScratch BvhLeafCollapse::buildScratch(uint32_t nodeCount, uint32_t primCount) {
    reserve(std::max(nodeCount, 1u), std::max(primCount, 1u));
    return {builtNodes_.data(), builtPrimIndices_.data()};
}

void BvhLeafCollapse::choose(const BvhNode* nodes, uint32_t nodeCount, cudaStream_t stream) {
    uint32_t* parents = parentsThenPairKept_.data();
    uint32_t* visits = reinterpret_cast<uint32_t*>(visitsThenPairStarts_.data());
    float* costs = reinterpret_cast<float*>(costsThenLeafPrimitives_.data());
    computeParents(nodes, nodeCount, parents, stream);
    PT_CUDA_CHECK(cudaMemsetAsync(visits, 0, nodeCount * sizeof(uint32_t), stream));
    PT_CUDA_CHECK(cudaMemsetAsync(choices_.data(), 0, nodeCount, stream));
    chooseKernel<<<bvhBlocks(nodeCount), kBvhBlockSize, 0, stream>>>(nodes, nodeCount, parents, visits,
                                                                     choices_.data(), costs);
    PT_CUDA_CHECK_LAUNCH("chooseKernel");
}

uint32_t BvhLeafCollapse::collapse(BvhNode* nodes, uint32_t nodeCount, uint32_t* primIndices,
                                   uint32_t primCount, cudaStream_t stream, const uint8_t* builtChoices) {
    if (primCount <= 1 || nodeCount <= 1) return nodeCount;  // the empty root or a single leaf
    const BuildScratch built = buildScratch(nodeCount, primCount);
    PT_CUDA_CHECK(
        cudaMemcpyAsync(built.nodes, nodes, nodeCount * sizeof(BvhNode), cudaMemcpyDeviceToDevice, stream));
    PT_CUDA_CHECK(cudaMemcpyAsync(built.primIndices, primIndices, primCount * sizeof(uint32_t),
                                  cudaMemcpyDeviceToDevice, stream));
    return collapseInto(built.nodes, nodeCount, built.primIndices, primCount, nodes, primIndices, stream,
                        builtChoices);
}

uint32_t BvhLeafCollapse::collapseInto(const BvhNode* builtNodes, uint32_t nodeCount,
                                       const uint32_t* builtPrimIndices, uint32_t primCount, BvhNode* nodes,
                                       uint32_t* primIndices, cudaStream_t stream,
                                       const uint8_t* builtChoices) {
    if (primCount <= 1 || nodeCount <= 1) {  // the empty root or a single leaf, as they are
        PT_CUDA_CHECK(cudaMemcpyAsync(nodes, builtNodes, nodeCount * sizeof(BvhNode),
                                      cudaMemcpyDeviceToDevice, stream));
        PT_CUDA_CHECK(cudaMemcpyAsync(primIndices, builtPrimIndices, primCount * sizeof(uint32_t),
                                      cudaMemcpyDeviceToDevice, stream));
        return nodeCount;
    }
    // A root and whole sibling pairs: an even count would have the passes read past the pairs.
    if (nodeCount % 2 == 0) {
        throw std::logic_error("BVH leaf collapse given " + std::to_string(nodeCount) +
                               " nodes: a tree of sibling pairs under a root has an odd count");
    }
    reserve(nodeCount, primCount);
    const uint32_t pairs = (nodeCount - 1) / 2;
    if (builtChoices == nullptr) choose(builtNodes, nodeCount, stream);
    const uint8_t* choices = builtChoices ? builtChoices : choices_.data();

    uint32_t* pairKept = parentsThenPairKept_.data();
    uint64_t* pairStarts = visitsThenPairStarts_.data();
    uint32_t* leafPrimitives = costsThenLeafPrimitives_.data();
    PT_CUDA_CHECK(cudaMemsetAsync(pairKept, 0, pairs * sizeof(uint32_t), stream));
    PT_CUDA_CHECK(cudaMemsetAsync(leafPrimitives, 0, nodeCount * sizeof(uint32_t), stream));
    markKernel<<<bvhBlocks(nodeCount), kBvhBlockSize, 0, stream>>>(builtNodes, nodeCount, choices, pairKept,
                                                                   leafPrimitives);
    PT_CUDA_CHECK_LAUNCH("markKernel");
    size_t scanBytes = scanScratch_.size();
    PT_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(scanScratch_.data(), scanBytes,
                                                pairWords(pairKept, leafPrimitives, pairs), pairStarts,
                                                int(pairs + 1), stream));
    writeKernel<<<bvhBlocks(nodeCount), kBvhBlockSize, 0, stream>>>(
        builtNodes, nodeCount, builtPrimIndices, primCount, choices, pairKept, leafPrimitives, pairStarts,
        nodes, primIndices);
    PT_CUDA_CHECK_LAUNCH("writeKernel");
    uint64_t totals = 0;
    PT_CUDA_CHECK(
        cudaMemcpyAsync(&totals, pairStarts + pairs, sizeof(totals), cudaMemcpyDeviceToHost, stream));
    PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    const uint32_t keptNodes = 1 + 2 * uint32_t(totals >> 32), placed = uint32_t(totals);
    // Every primitive lands in exactly one kept leaf: any other total is a defect here (or a
    // tree not in the GPU builders' layout), which must not pass silently.
    if (placed != primCount || keptNodes > nodeCount) {
        throw std::logic_error("BVH leaf collapse placed " + std::to_string(placed) + " of " +
                               std::to_string(primCount) + " primitives in " + std::to_string(keptNodes) +
                               " of " + std::to_string(nodeCount) + " nodes");
    }
    return keptNodes;
}

}  // namespace pt::cuda
