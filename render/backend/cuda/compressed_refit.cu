// requantizeCompressedNodes (gpu_bvh.h): after a refit of a BLAS's binary nodes, its compressed
// 8-wide nodes take their boxes from them again (render/bvh/compressed_wide_quantize.h, the code
// the host collapse runs). One thread per compressed node; the topology is kept.
// gatherLeafTriangles: the leaves' triangles take their corners from the moved positions
// (render/bvh/gather_leaf_triangles.h, as the host collapse gathers them). One thread an entry.
#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/bvh/compressed_wide_quantize.h"
#include "render/bvh/gather_leaf_triangles.h"

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

__global__ void gatherKernel(LeafTriangle* out, const uint32_t* prims, uint32_t count,
                             const TriangleIndices* triangles, const Vec3* positions, BlasRef blas) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    out[i] = gatherLeafTriangle(triangles, positions, blas, prims[i]);
}

}  // namespace

void gatherLeafTriangles(LeafTriangle* out, const uint32_t* prims, uint32_t count,
                         const TriangleIndices* triangles, const Vec3* positions, const BlasRef& blas,
                         cudaStream_t stream) {
    if (count == 0) return;
    gatherKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(out, prims, count, triangles, positions,
                                                                 blas);
    PT_CUDA_CHECK_LAUNCH("gatherLeafTriangles");
}

void requantizeCompressedNodes(CompressedWideNode* nodes, uint32_t count, const BvhNode* binary,
                               const uint32_t* sourceNodes, cudaStream_t stream) {
    if (count == 0) return;
    requantizeKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(nodes, count, binary, sourceNodes);
    PT_CUDA_CHECK_LAUNCH("requantizeKernel");
}

}  // namespace pt::cuda
