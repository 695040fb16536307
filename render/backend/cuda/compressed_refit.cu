// requantizeCompressedNodes (gpu_bvh.h): after a refit of a BLAS's binary nodes, its compressed
// 8-wide nodes take their boxes from them again (render/bvh/compressed_wide_quantize.h, the code
// the host collapse runs). One thread per compressed node; the topology is kept.
#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/bvh/compressed_wide_quantize.h"

namespace pt::cuda {

namespace {

__global__ void requantizeKernel(CompressedWideNode* nodes, uint32_t count, const BvhNode* binary,
                                 const uint32_t* sourceNodes) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    CompressedWideNode node = nodes[i];
    quantizeWideBoxes(node, binary, sourceNodes + size_t(i) * CompressedWideNode::kWidth);
    nodes[i] = node;
}

}  // namespace

void requantizeCompressedNodes(CompressedWideNode* nodes, uint32_t count, const BvhNode* binary,
                               const uint32_t* sourceNodes, cudaStream_t stream) {
    if (count == 0) return;
    requantizeKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(nodes, count, binary, sourceNodes);
    PT_CUDA_CHECK_LAUNCH("requantizeKernel");
}

}  // namespace pt::cuda
