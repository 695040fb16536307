#pragma once
// The bottom-up climb shared by the LBVH builder, the refit and the leaf collapse (device code,
// nvcc only), and its box pass:
// the thread that finished a node's box climbs to its parent; of the two children's threads
// the second to arrive (an atomic counter per node) computes the parent's box, the first stops.
// Every node is thus written exactly once, after both of its children, with no global barrier.
#include <cuda_runtime.h>

#include <cstdint>

#include "render/bvh/aabb.h"
#include "render/kernel/bvh_node.h"

namespace pt::cuda {

// The box of `node` as L2 holds it: __ldcg skips L1, which is not coherent across SMs and may
// hold a line read before another SM wrote the box.
__device__ __forceinline__ Aabb loadBoxCoherent(const BvhNode* node) {
    const float4* words = reinterpret_cast<const float4*>(node);
    const float4 lo = __ldcg(words), hi = __ldcg(words + 1);
    Aabb box;
    box.lo = Vec3(lo.x, lo.y, lo.z);
    box.hi = Vec3(hi.x, hi.y, hi.z);
    return box;
}

// Writes the box and leaves leftOrFirst and count as they are.
__device__ __forceinline__ void storeBox(BvhNode* node, const Aabb& box) {
    __stcg(&node->lo.x, box.lo.x);
    __stcg(&node->lo.y, box.lo.y);
    __stcg(&node->lo.z, box.lo.z);
    __stcg(&node->hi.x, box.hi.x);
    __stcg(&node->hi.y, box.hi.y);
    __stcg(&node->hi.z, box.hi.z);
}

// The climb itself, for any bottom-up pass. Called by the thread that has just stored what its
// pass computes of `node`: climbs while it is the second of two siblings' threads to arrive
// (an atomic counter per node), calling finishParent(parent), which computes the parent from
// both children and returns whether to climb on. `parentOf(i)` is the index of node i's parent
// (i > 0); `visits` holds one zeroed counter per node, indexed like the nodes.
template <class ParentOf, class FinishParent>
__device__ void climbAsSecondArrival(uint32_t node, uint32_t* visits, ParentOf parentOf,
                                     FinishParent finishParent) {
    while (node != 0) {
        const uint32_t parent = parentOf(node);
        __threadfence();  // release: this node's result is visible before the arrival is counted
        if (atomicAdd(&visits[parent], 1u) == 0) return;  // the sibling's thread will finish
        __threadfence();  // acquire: the sibling's result, fenced before its arrival, is read after ours
        if (!finishParent(parent)) return;
        node = parent;
    }
}

// Called by the thread that has just stored the final box of `node`. The children of every
// interior node (leftOrFirst, count) must already be in `nodes`.
template <class ParentOf>
__device__ void propagateBoxesUp(BvhNode* nodes, uint32_t node, uint32_t* visits, ParentOf parentOf) {
    climbAsSecondArrival(node, visits, parentOf, [&](uint32_t parent) {
        const uint32_t left = nodes[parent].leftOrFirst;  // topology: not written by this pass
        Aabb box = loadBoxCoherent(nodes + left);
        box.grow(loadBoxCoherent(nodes + left + 1));
        storeBox(nodes + parent, box);
        return true;
    });
}

// Launch shape of the one-thread-per-item kernels here.
constexpr uint32_t kBvhBlockSize = 256;
inline uint32_t bvhBlocks(uint32_t items) { return (items + kBvhBlockSize - 1) / kBvhBlockSize; }

}  // namespace pt::cuda
