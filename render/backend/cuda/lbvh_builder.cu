// LbvhBuilder::build (gpu_bvh.h): Karras 2012. Passes, all queued on the caller's stream:
//   1-3. keys sorted by the Morton code of the box centres (MortonSort, morton_sort.h)
//   4. one thread per internal node: its key range, its split, its children's node slots
//   5. one thread per leaf: the leaf node, then boxes bottom-up (bvh_bottom_up.cuh)
#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"

namespace pt::cuda {

namespace {

// Length of the common prefix of sorted keys i and j; -1 for j outside [0, count).
__device__ __forceinline__ int commonPrefix(const uint64_t* keys, int64_t count, int64_t i, int64_t j) {
    if (j < 0 || j >= count) return -1;
    return __clzll(keys[i] ^ keys[j]);  // keys are unique: the XOR is never 0
}

// Karras's internal node i: the range of keys it covers, the split within it, and where its
// children go. Writes the topology (leftOrFirst, count) of internal children; leaves are
// written by the bottom-up pass, which looks their slots up in leafSlots.
__global__ void karrasNodesKernel(const uint64_t* keys, uint32_t count, BvhNode* nodes, uint32_t* leafSlots,
                                  uint32_t* internalSlots) {
    const uint32_t index = blockIdx.x * blockDim.x + threadIdx.x;
    if (index + 1 >= count) return;
    const int64_t n = count, i = index;
    const int64_t d = commonPrefix(keys, n, i, i + 1) > commonPrefix(keys, n, i, i - 1) ? 1 : -1;
    // The far end of the range: exponential search, then binary search.
    const int minPrefix = commonPrefix(keys, n, i, i - d);
    int64_t maxLength = 2;
    while (commonPrefix(keys, n, i, i + maxLength * d) > minPrefix) maxLength *= 2;
    int64_t length = 0;
    for (int64_t t = maxLength / 2; t >= 1; t /= 2) {
        if (commonPrefix(keys, n, i, i + (length + t) * d) > minPrefix) length += t;
    }
    const int64_t j = i + length * d;
    // The split: the last key sharing more than the range's common prefix with key i.
    const int nodePrefix = commonPrefix(keys, n, i, j);
    int64_t split = 0, t = length;
    do {
        t = (t + 1) >> 1;
        if (commonPrefix(keys, n, i, i + (split + t) * d) > nodePrefix) split += t;
    } while (t > 1);
    const int64_t gamma = i + split * d + (d < 0 ? -1 : 0);

    const uint32_t children[2] = {uint32_t(gamma), uint32_t(gamma + 1)};
    const bool leaves[2] = {(i < j ? i : j) == gamma, (i > j ? i : j) == gamma + 1};
    for (uint32_t side = 0; side < 2; ++side) {
        const uint32_t slot = 1 + 2 * index + side;
        if (leaves[side]) {
            leafSlots[children[side]] = slot;
        } else {
            internalSlots[children[side]] = slot;
            nodes[slot].leftOrFirst = 1 + 2 * children[side];
            nodes[slot].count = 0;
        }
    }
    if (index == 0) {
        internalSlots[0] = 0;
        nodes[0].leftOrFirst = 1;
        nodes[0].count = 0;
    }
}

struct LbvhParent {
    const uint32_t* internalSlots;
    // Node c > 0 is child 0 or 1 of Karras internal node (c - 1) / 2.
    __device__ uint32_t operator()(uint32_t c) const { return internalSlots[(c - 1) >> 1]; }
};

__global__ void lbvhLeavesAndBoxesKernel(const Aabb* boxes, const uint64_t* sortedKeys, uint32_t count,
                                         const uint32_t* leafSlots, const uint32_t* internalSlots,
                                         BvhNode* nodes, uint32_t* primIndices, uint32_t* visits) {
    const uint32_t q = blockIdx.x * blockDim.x + threadIdx.x;
    if (q >= count) return;
    const uint32_t prim = uint32_t(sortedKeys[q]);  // the low 32 bits
    primIndices[q] = prim;
    const Aabb box = boxes[prim];
    const uint32_t slot = leafSlots[q];
    BvhNode leaf;
    leaf.lo = box.lo;
    leaf.leftOrFirst = q;
    leaf.hi = box.hi;
    leaf.count = 1;
    nodes[slot] = leaf;
    propagateBoxesUp(nodes, slot, visits, LbvhParent{internalSlots});
}

// count 0: the empty root; count 1: a single leaf root.
__global__ void trivialTreeKernel(const Aabb* boxes, uint32_t count, BvhNode* nodes, uint32_t* primIndices) {
    BvhNode root;
    const Aabb box = count == 1 ? boxes[0] : Aabb{};
    root.lo = box.lo;
    root.leftOrFirst = 0;
    root.hi = box.hi;
    root.count = count;
    nodes[0] = root;
    if (count == 1) primIndices[0] = 0;
}

}  // namespace

void LbvhBuilder::reserve(uint32_t count) {
    if (count <= capacity_) return;
    const uint32_t capacity = grownCapacity(count, capacity_);
    leafSlots_.resize(capacity);
    internalSlots_.resize(capacity);
    visits_.resize(lbvhNodeCount(capacity));
    capacity_ = capacity;
}

void LbvhBuilder::release() {
    morton_.release();
    leafSlots_ = {};
    internalSlots_ = {};
    visits_ = {};
    capacity_ = 0;
}

void LbvhBuilder::build(const Aabb* boxes, uint32_t count, BvhNode* nodes, uint32_t* primIndices,
                        cudaStream_t stream) {
    if (count <= 1) {
        trivialTreeKernel<<<1, 1, 0, stream>>>(boxes, count, nodes, primIndices);
        PT_CUDA_CHECK_LAUNCH("trivialTreeKernel");
        return;
    }
    buildFromSortedKeys(boxes, morton_.sort(boxes, count, stream), count, nodes, primIndices, stream);
}

void LbvhBuilder::buildFromSortedKeys(const Aabb* boxes, const uint64_t* sorted, uint32_t count,
                                      BvhNode* nodes, uint32_t* primIndices, cudaStream_t stream) {
    reserve(count);
    karrasNodesKernel<<<bvhBlocks(count - 1), kBvhBlockSize, 0, stream>>>(
        sorted, count, nodes, leafSlots_.data(), internalSlots_.data());
    PT_CUDA_CHECK_LAUNCH("karrasNodesKernel");
    const uint32_t nodeCount = lbvhNodeCount(count);
    PT_CUDA_CHECK(cudaMemsetAsync(visits_.data(), 0, nodeCount * sizeof(uint32_t), stream));
    lbvhLeavesAndBoxesKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(
        boxes, sorted, count, leafSlots_.data(), internalSlots_.data(), nodes, primIndices, visits_.data());
    PT_CUDA_CHECK_LAUNCH("lbvhLeavesAndBoxesKernel");
}

}  // namespace pt::cuda
