// computePrimitiveBoxes (gpu_bvh.h): the object-space box of every primitive of one BLAS,
// through the same functions the CPU scene compiler uses (render/bvh/primitive_bounds.h).
#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/bvh/primitive_bounds.h"

namespace pt::cuda {

namespace {

__global__ void triangleBoxesKernel(const Vec3* positions, const TriangleIndices* triangles, uint32_t count,
                                    Aabb* boxes) {
    const uint32_t p = blockIdx.x * blockDim.x + threadIdx.x;
    if (p >= count) return;
    const TriangleIndices t = triangles[p];
    boxes[p] = triangleBounds(positions[t.v0], positions[t.v1], positions[t.v2]);
}

__global__ void sphereBoxesKernel(const Vec4* spheres, uint32_t count, Aabb* boxes) {
    const uint32_t p = blockIdx.x * blockDim.x + threadIdx.x;
    if (p >= count) return;
    boxes[p] = sphereBounds(spheres[p]);
}

}  // namespace

void computePrimitiveBoxes(const RenderScene& scene, const BlasRef& blas, Aabb* boxes, cudaStream_t stream) {
    const uint32_t count = blas.primitiveCount;
    if (count == 0) return;
    if (blas.kind == GeometryKind::Spheres) {
        sphereBoxesKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(
            scene.spheres.data + blas.primitiveOffset, count, boxes);
        PT_CUDA_CHECK_LAUNCH("sphereBoxesKernel");
    } else {
        triangleBoxesKernel<<<bvhBlocks(count), kBvhBlockSize, 0, stream>>>(
            scene.positions.data, scene.triangles.data + blas.primitiveOffset, count, boxes);
        PT_CUDA_CHECK_LAUNCH("triangleBoxesKernel");
    }
}

}  // namespace pt::cuda
