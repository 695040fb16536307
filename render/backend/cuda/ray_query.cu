// Traversal alone over a batch of rays: what benchmarks time as Mrays/s and picking asks.
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/wavefront_kernels.h"
#include "render/bvh/traversal.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kBlock = 128;

// The traversal code a scene needs (feature_set.h), as the path kernels' variants choose theirs
// (kernel_variants.h): a scene of one instance walks its BLAS without a TLAS. A kernel's
// registers are those of its heaviest path, and the TLAS walk keeps its own state live under
// every BLAS walk: the generic kernel takes 108 registers (ptxas, sm_90) where the one-instance
// kernel takes 72 (closest hit; 70 for any hit), so timing a one-instance scene with it measured
// the TLAS, not the walk (H200, 1080p, 1M-triangle sphere, Mrays/s primary / diffuse / shadow:
// 2231 / 1197 / 167 with the generic kernel, 2895 / 1527 / 1036 with this one). Instanced
// scenes keep the generic kernel: one for them without the brute-force loop took as many
// registers but traced Balloon's shadow rays slower (206 against 243 Mrays/s; camera and
// diffuse rays alike).
constexpr FeatureSet kSingleInstanceTraversal =
    kAllFeatures & ~(feature::kMultipleInstances | feature::kBruteForce);

template <FeatureSet kF, bool kAnyHit>
__global__ void traceRaysKernel(RenderScene scene, const Ray* rays, uint32_t count, Hit* hits) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const Ray ray = rays[i];
    Hit hit;
    if (kAnyHit) {
        hit = Hit{};
        hit.instance = intersectAny<kF>(scene, ray) ? 0u : Hit::kNoHit;
    } else {
        intersectClosest<kF>(scene, ray, hit);
    }
    hits[i] = hit;
}

template <FeatureSet kF>
void launchWith(const RenderScene& scene, const Ray* rays, uint32_t count, bool anyHit, Hit* hits,
                cudaStream_t stream) {
    const uint32_t blocks = (count + kBlock - 1) / kBlock;
    if (anyHit) {
        traceRaysKernel<kF, true><<<blocks, kBlock, 0, stream>>>(scene, rays, count, hits);
    } else {
        traceRaysKernel<kF, false><<<blocks, kBlock, 0, stream>>>(scene, rays, count, hits);
    }
    PT_CUDA_CHECK_LAUNCH("traceRaysKernel");
}

}  // namespace

void launchTraceRays(const RenderScene& scene, const Ray* rays, uint32_t count, bool anyHit, Hit* hits,
                     cudaStream_t stream) {
    if (count == 0) return;
    if (scene.bruteForce || scene.instances.count > 1) {
        launchWith<kAllFeatures>(scene, rays, count, anyHit, hits, stream);
    } else {
        launchWith<kSingleInstanceTraversal>(scene, rays, count, anyHit, hits, stream);
    }
}

}  // namespace pt::cuda
