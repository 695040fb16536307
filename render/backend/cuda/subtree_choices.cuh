#pragma once
// What the leaf collapse (BvhLeafCollapse, render/bvh/subtree_collapse.h) needs to know of each
// node of a GPU-built tree, one byte a node (device code, nvcc only). The collapse works the
// bytes out itself, climbing from the leaves; the PLOC builders write them as they merge
// (ploc_clusters.cuh), since every merge already holds both children, which spares the
// collapse its climb (on an H200 at 1M primitives, its parent links and choices took 216 us of
// its 0.35-0.43 ms).
#include <cuda_runtime.h>

#include <cstdint>

#include "render/bvh/subtree_collapse.h"

namespace pt::cuda {

// A node's choice: bits 0-6 the primitives below it (0: more than kMaxCollapsedLeaf), bit 7 set
// where it is to be a leaf (a leaf already, or collapsed).
constexpr uint8_t kChoiceLeaf = 0x80;
constexpr uint8_t kChoicePrimitives = 0x7F;
static_assert(kMaxCollapsedLeaf <= kChoicePrimitives, "the primitive count fits below the leaf bit");

__device__ __forceinline__ uint8_t choiceByte(const SubtreeChoice& choice) {
    return uint8_t(choice.primitives | (choice.asLeaf ? kChoiceLeaf : 0));
}

// The sibling pair a left child opens: the GPU builders put the children of every interior
// node at slots 2p + 1 and 2p + 2.
__device__ __forceinline__ uint32_t pairOf(uint32_t leftChild) { return (leftChild - 1) / 2; }

// Where a builder writes the choices as it merges: `choices` one byte a node slot;
// `pairCosts`, the optimal cost of each subtree of fewer than kMaxCollapsedLeaf primitives (the
// only ones a parent's merge can still collapse with a sibling), indexed by the pair its
// children sit in.
struct SubtreeChoiceArrays {
    uint8_t* choices = nullptr;
    float* pairCosts = nullptr;
};

}  // namespace pt::cuda
