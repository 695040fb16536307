// The megakernel schedule: one thread runs tracePath, the same loop the CPU backend runs, for
// one sample of one pixel, compiled once per kernel variant (kernel_variants.h).
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/register_cap.cuh"
#include "render/backend/cuda/variant_dispatch.cuh"
#include "render/backend/cuda/warp_atomics.cuh"
#include "render/backend/cuda/wavefront_kernels.h"
#include "render/integrator/path_tracer.h"

namespace pt::cuda {

namespace {

// Threads a block. With the register cap held, 64 and 256 measured no better on the H100
// (render --megakernel at 1080p, spp/s, 128 / 256 / 64: Cornell 101.9 / 98.5 / 101.0, Balloon
// 362.5 / 363.4 / 360.0, 1M-triangle sphere 503 / 487 / 501, 10M 322 / 305 / 323).
constexpr uint32_t kBlock = 128;

// kF: the variant's feature set. kAovs: whether the path records AOVs; without, the kernel has
// no AOV code.
// Registers are capped at 64 a thread (with blocks of 128, 8 blocks an SM and 50% theoretical
// occupancy, against 25% or less uncapped): the spills this causes (local memory, cached in
// L1) cost less than the latency the extra warps hide, in a kernel that mostly waits on BVH
// loads and instruction fetch. Measured on the H100, render --megakernel at 1080p, spp/s
// uncapped and with caps of 128 / 96 / 80 / 72 / 64 / 48 / 40 registers:
//   Cornell box     66.1 | 67.3  73.4  89.6  92.4  99.2  99.0  85.1
//   Balloon         304  | 313   314   320   325   327   326   308
//   1M-tri sphere   395  | 396   432   471   497   510   481   459
//   10M-tri sphere  -    | -     278   295   313   325   304   274
// PT_MEGAKERNEL_REGISTERS overrides it for such experiments.
#ifndef PT_MEGAKERNEL_REGISTERS
#define PT_MEGAKERNEL_REGISTERS 64
#endif
constexpr uint32_t kMinBlocks = blocksPerSmFor(kBlock, PT_MEGAKERNEL_REGISTERS);

template <uint32_t kF, bool kAovs>
__global__ void __launch_bounds__(kBlock, kMinBlocks) megakernel(RenderScene scene, WaveBuffers b, WaveShape shape) {
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
