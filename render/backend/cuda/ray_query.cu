// Traversal alone over a batch of rays: what benchmarks time as Mrays/s and picking asks.
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/wavefront_kernels.h"
#include "render/bvh/traversal.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kBlock = 128;

template <bool kAnyHit>
__global__ void traceRaysKernel(RenderScene scene, const Ray* rays, uint32_t count, Hit* hits) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const Ray ray = rays[i];
    Hit hit;
    if (kAnyHit) {
        hit = Hit{};
        hit.instance = intersectAny(scene, ray) ? 0u : Hit::kNoHit;
    } else {
        intersectClosest(scene, ray, hit);
    }
    hits[i] = hit;
}

}  // namespace

void launchTraceRays(const RenderScene& scene, const Ray* rays, uint32_t count, bool anyHit, Hit* hits,
                     cudaStream_t stream) {
    if (count == 0) return;
    const uint32_t blocks = (count + kBlock - 1) / kBlock;
    if (anyHit) {
        traceRaysKernel<true><<<blocks, kBlock, 0, stream>>>(scene, rays, count, hits);
    } else {
        traceRaysKernel<false><<<blocks, kBlock, 0, stream>>>(scene, rays, count, hits);
    }
    PT_CUDA_CHECK_LAUNCH("traceRaysKernel");
}

}  // namespace pt::cuda
