// sahCostOnDevice (gpu_bvh.h): render/bvh/sah_cost.cpp's number, summed on the device. Each
// node's area is computed in float exactly as the host computes it and summed in double, in a
// fixed order (per-block partial sums, then one block over the partials), so the result is
// reproducible and agrees with the host to float rounding.
#include <algorithm>
#include <cub/block/block_reduce.cuh>

#include "render/backend/cuda/gpu_bvh.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kSahBlockSize = 256;
constexpr uint32_t kSahMaxBlocks = 1024;
using SahBlockReduce = cub::BlockReduce<double, kSahBlockSize>;

__device__ __forceinline__ float nodeArea(const BvhNode& node) {
    Aabb box;
    box.lo = node.lo;
    box.hi = node.hi;
    return box.surfaceArea();
}

// traversalCost = intersectionCost = 1. With a root of zero area every node counts as if it
// had the root's area (sah_cost.h).
__device__ __forceinline__ double sahTerm(const BvhNode& node, bool rootHasArea) {
    const double area = rootHasArea ? double(nodeArea(node)) : 1.0;
    return node.isLeaf() ? double(node.count) * area : area;
}

__global__ void sahPartialSumsKernel(const BvhNode* nodes, uint32_t nodeCount, double* partials) {
    __shared__ typename SahBlockReduce::TempStorage scratch;
    const bool rootHasArea = nodeArea(nodes[0]) > 0.0f;
    double sum = 0.0;
    for (uint32_t i = blockIdx.x * blockDim.x + threadIdx.x; i < nodeCount; i += gridDim.x * blockDim.x) {
        sum += sahTerm(nodes[i], rootHasArea);
    }
    const double blockSum = SahBlockReduce(scratch).Sum(sum);
    if (threadIdx.x == 0) partials[blockIdx.x] = blockSum;
}

__global__ void sahFinishKernel(const BvhNode* nodes, uint32_t nodeCount, const double* partials,
                                uint32_t partialCount, float* cost) {
    __shared__ typename SahBlockReduce::TempStorage scratch;
    double sum = 0.0;
    for (uint32_t i = threadIdx.x; i < partialCount; i += blockDim.x) sum += partials[i];
    const double total = SahBlockReduce(scratch).Sum(sum);
    if (threadIdx.x != 0) return;
    const double rootArea = nodeArea(nodes[0]);
    const bool empty = nodeCount == 1 && !nodes[0].isLeaf();  // no primitives: the host says 0
    *cost = empty ? 0.0f : float(rootArea > 0.0 ? total / rootArea : total);
}

}  // namespace

float sahCostOnDevice(const BvhNode* nodes, uint32_t nodeCount, cudaStream_t stream) {
    if (nodeCount == 0) return 0.0f;
    const uint32_t blocks = std::min(kSahMaxBlocks, (nodeCount + kSahBlockSize - 1) / kSahBlockSize);
    void* scratch = nullptr;
    PT_CUDA_CHECK(cudaMallocAsync(&scratch, blocks * sizeof(double) + sizeof(float), stream));
    double* partials = static_cast<double*>(scratch);
    float* cost = reinterpret_cast<float*>(partials + blocks);
    sahPartialSumsKernel<<<blocks, kSahBlockSize, 0, stream>>>(nodes, nodeCount, partials);
    PT_CUDA_CHECK_LAUNCH("sahPartialSumsKernel");
    sahFinishKernel<<<1, kSahBlockSize, 0, stream>>>(nodes, nodeCount, partials, blocks, cost);
    PT_CUDA_CHECK_LAUNCH("sahFinishKernel");
    float result = 0.0f;
    PT_CUDA_CHECK(cudaMemcpyAsync(&result, cost, sizeof(float), cudaMemcpyDeviceToHost, stream));
    PT_CUDA_CHECK(cudaFreeAsync(scratch, stream));
    PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    return result;
}

}  // namespace pt::cuda
