// computePrimitiveBoxes (gpu_bvh.h): the object-space box of every primitive of one BLAS, as
// the CPU scene compiler computes it for the binned builder (compile_geometry.cpp's
// primitiveBounds): a triangle's three vertices, a sphere's centre -/+ radius, grown in that
// order, so both sides produce the same boxes bit for bit.
#include "render/backend/cuda/bvh_bottom_up.cuh"
#include "render/backend/cuda/gpu_bvh.h"

namespace pt::cuda {

namespace {

__global__ void triangleBoxesKernel(const Vec3* positions, const TriangleIndices* triangles, uint32_t count,
                                    Aabb* boxes) {
    const uint32_t p = blockIdx.x * blockDim.x + threadIdx.x;
    if (p >= count) return;
    const TriangleIndices t = triangles[p];
    Aabb box;
    box.grow(positions[t.v0]);
    box.grow(positions[t.v1]);
    box.grow(positions[t.v2]);
    boxes[p] = box;
}

__global__ void sphereBoxesKernel(const Vec4* spheres, uint32_t count, Aabb* boxes) {
    const uint32_t p = blockIdx.x * blockDim.x + threadIdx.x;
    if (p >= count) return;
    const Vec4 s = spheres[p];
    Aabb box;
    box.grow(s.xyz() - Vec3(s.w));
    box.grow(s.xyz() + Vec3(s.w));
    boxes[p] = box;
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
