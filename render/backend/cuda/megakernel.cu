// The megakernel schedule: one thread runs tracePath, the same loop the CPU backend runs, for
// one sample of one pixel, compiled once per kernel variant (kernel_variants.h).
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/variant_dispatch.cuh"
#include "render/backend/cuda/warp_atomics.cuh"
#include "render/backend/cuda/wavefront_kernels.h"
#include "render/integrator/path_tracer.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kBlock = 128;

// kF: the variant's feature set. kAovs: whether the path records AOVs; without, the kernel has
// no AOV code.
template <uint32_t kF, bool kAovs>
__global__ void megakernel(RenderScene scene, WaveBuffers b, WaveShape shape) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= shape.pathCount) return;
    const uint32_t pixel = i % shape.pixelCount, sample = shape.firstSample + i / shape.pixelCount;
    const uint32_t width = scene.settings.width;
    PathCounters counters;
    AovSample aov;
    const Vec3 radiance = tracePath<kAovs, kF>(scene, pixel % width, pixel / width, sample, counters, &aov);
    if (kAovs) {
        addAovSample(b.aovs, pixel, sample, aov);
        addAovCost(b.aovs, pixel, aov.cost);
    }
    b.radiance[3 * i + 0] = radiance.x;
    b.radiance[3 * i + 1] = radiance.y;
    b.radiance[3 * i + 2] = radiance.z;
    warpAtomicAdd(&b.counters->rays, uint32_t(counters.rays));
    warpAtomicAdd(&b.counters->nonfinite, uint32_t(counters.nonfiniteSamples));
}

}  // namespace

const void* megakernelSymbol(uint32_t variant) {
    const void* symbol = nullptr;
    forKernelVariant(variant, [&](auto features) {
        symbol = reinterpret_cast<const void*>(megakernel<decltype(features)::value, false>);
    });
    return symbol;
}

void launchMegakernel(uint32_t variant, const RenderScene& scene, const WaveBuffers& b,
                      const WaveShape& shape, cudaStream_t stream) {
    const uint32_t blocks = (shape.pathCount + kBlock - 1) / kBlock;
    if (b.aovs.mask & kPathAovs) {  // AOVs run the generic code (kernel_variants.h)
        megakernel<kAllFeatures, true><<<blocks, kBlock, 0, stream>>>(scene, b, shape);
    } else {
        forKernelVariant(variant, [&](auto features) {
            megakernel<decltype(features)::value, false><<<blocks, kBlock, 0, stream>>>(scene, b, shape);
        });
    }
    PT_CUDA_CHECK_LAUNCH("megakernel");
}

}  // namespace pt::cuda
