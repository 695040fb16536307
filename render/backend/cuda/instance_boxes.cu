// computeInstanceBoxes (gpu_bvh.h): the TLAS input on the device, through the same
// instanceBounds the CPU scene compiler uses (render/bvh/instance_bounds.h).
#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/bvh/instance_bounds.h"

namespace pt::cuda {

namespace {

__global__ void instanceBoxesKernel(const RenderInstance* instances, uint32_t count, const BlasRef* blases,
                                    const BvhNode* blasNodes, Aabb* boxes) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const RenderInstance& instance = instances[i];
    const BvhNode root = blasNodes[blases[instance.blas].nodeOffset];
    boxes[i] = instanceBounds(root, instance.objectToWorld);
}

}  // namespace

void computeInstanceBoxes(const RenderInstance* instances, uint32_t count, const BlasRef* blases,
                          const BvhNode* blasNodes, Aabb* boxes, cudaStream_t stream) {
    if (count == 0) return;
    instanceBoxesKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(instances, count, blases, blasNodes,
                                                                        boxes);
    PT_CUDA_CHECK_LAUNCH("instanceBoxesKernel");
}

}  // namespace pt::cuda
