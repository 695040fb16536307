// computeParents and refitBvh (gpu_bvh.h): bottom-up refit of any BVH in the canonical layout,
// CPU-built (leaves of several primitives) or LBVH alike. One thread per node; the leaves'
// threads compute their boxes from the primitives' boxes and climb (bvh_bottom_up.cuh).
#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"

namespace pt::cuda {

namespace {

__global__ void parentsKernel(const BvhNode* nodes, uint32_t nodeCount, uint32_t* parents) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= nodeCount) return;
    if (i == 0) parents[0] = ~0u;
    const BvhNode node = nodes[i];
    // An interior node without room for children is the empty root (count 0, nothing below).
    if (node.isLeaf() || node.leftOrFirst + 1 >= nodeCount) return;
    parents[node.leftOrFirst] = i;
    parents[node.leftOrFirst + 1] = i;
}

struct ParentFromTable {
    const uint32_t* parents;
    __device__ uint32_t operator()(uint32_t node) const { return parents[node]; }
};

__global__ void refitKernel(BvhNode* nodes, uint32_t nodeCount, const uint32_t* parents,
                            const uint32_t* primIndices, const Aabb* primBoxes, uint32_t* visits) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= nodeCount) return;
    const BvhNode node = nodes[i];  // topology only: boxes are not read before this thread writes them
    if (!node.isLeaf()) return;
    Aabb box;
    for (uint32_t k = node.leftOrFirst; k < node.leftOrFirst + node.count; ++k)
        box.grow(primBoxes[primIndices[k]]);
    storeBox(nodes + i, box);
    propagateBoxesUp(nodes, i, visits, ParentFromTable{parents});
}

}  // namespace

void computeParents(const BvhNode* nodes, uint32_t nodeCount, uint32_t* parents, cudaStream_t stream) {
    if (nodeCount == 0) return;
    parentsKernel<<<bvhBlocks(nodeCount), kBvhBlockSize, 0, stream>>>(nodes, nodeCount, parents);
    PT_CUDA_CHECK_LAUNCH("parentsKernel");
}

void refitBvh(BvhNode* nodes, uint32_t nodeCount, const uint32_t* parents, const uint32_t* primIndices,
              const Aabb* primBoxes, uint32_t* visits, cudaStream_t stream) {
    if (nodeCount == 0) return;
    PT_CUDA_CHECK(cudaMemsetAsync(visits, 0, nodeCount * sizeof(uint32_t), stream));
    refitKernel<<<bvhBlocks(nodeCount), kBvhBlockSize, 0, stream>>>(nodes, nodeCount, parents, primIndices,
                                                                    primBoxes, visits);
    PT_CUDA_CHECK_LAUNCH("refitKernel");
}

}  // namespace pt::cuda
