// The megakernel schedule: one thread runs whole paths, the loop the CPU backend runs (tracePath's
// fused steps), compiled once per kernel variant (kernel_variants.h).

#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/persistent_grid.cuh"
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

constexpr unsigned kFullWarp = 0xffffffffu;
constexpr uint32_t kNoPath = ~0u;

// One thread a path, for paths that record AOVs (tracePath's plain loop, with the AOV code).
__global__ void __launch_bounds__(kBlock, kMinBlocks)
    aovMegakernel(RenderScene scene, WaveBuffers b, WaveShape shape) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= shape.pathCount) return;
    const uint32_t pixel = i % shape.pixelCount, sample = shape.firstSample + i / shape.pixelCount;
    const uint32_t width = scene.settings.width;
    PathCounters counters;
    AovSample aov;
    const Vec3 radiance =
        tracePath<true, kAllFeatures>(scene, pixel % width, pixel / width, sample, counters, &aov);
    addAovSample(b.aovs, pixel, sample, aov);
    addAovCost(b.aovs, pixel, aov.cost);
    b.radiance[3 * i + 0] = radiance.x;
    b.radiance[3 * i + 1] = radiance.y;
    b.radiance[3 * i + 2] = radiance.z;
    warpAtomicAdd(&b.counters->rays, uint32_t(counters.rays));
    warpAtomicAdd(&b.counters->nonfinite, uint32_t(counters.nonfiniteSamples));
}

// Persistent threads with path regeneration. The grid holds as many threads as the GPU keeps
// resident, and each takes paths of the wave from a counter (RenderCounters::claimedPaths), as
// the persistent traversal kernels of Aila and Laine 2009 ("Understanding the efficiency of ray
// traversal on GPUs") take rays. Each iteration traces one ray of each lane's path (the fused
// step of path_tracer.h, so the images are those of tracePath bit for bit). With
// `regeneration`, a lane whose path ended generates the next one in the same iteration (Novak,
// Havran and Dachsbacher 2010, "Path regeneration for interactive path tracing"), so a warp no
// longer runs with ever fewer lanes until its longest path ends; without, lanes wait for the
// whole warp, as with one path a thread.
// kF: the variant's feature set; the AOV kernel above alone has AOV code.
template <FeatureSet kF>
__global__ void __launch_bounds__(kBlock, kMinBlocks)
    megakernel(RenderScene scene, WaveBuffers b, WaveShape shape, bool regeneration) {
    const uint32_t width = scene.settings.width;
    PathCounters counters;
    PathState state;
    ShadowRay shadow{};
    uint32_t path = kNoPath;
    bool exhausted = false;  // the wave has no paths left to take
    // Every lane runs every iteration (whole warps, no early exit), so the votes take all 32.
    for (;;) {
        const bool idle = path == kNoPath;
        const bool warpIdle = __all_sync(kFullWarp, idle);
        if (idle && !exhausted && (regeneration || warpIdle)) {
            const uint32_t claimed = warpReserve(&b.counters->claimedPaths, true);
            if (claimed < shape.pathCount) {
                path = claimed;
                const uint32_t pixel = path % shape.pixelCount;
                state = generatePath<kF>(scene, pixel % width, pixel / width,
                                         shape.firstSample + path / shape.pixelCount);
                shadow.valid = false;
            } else {
                exhausted = true;
            }
        }
        if (__all_sync(kFullWarp, path == kNoPath)) break;
        if (path != kNoPath) {
            traceFusedStep<kF>(scene, state, shadow, counters);
            if (fusedPathDone(state, shadow)) {
                const Vec3 radiance = finishedRadiance(state, counters);
                b.radiance[3 * path + 0] = radiance.x;
                b.radiance[3 * path + 1] = radiance.y;
                b.radiance[3 * path + 2] = radiance.z;
                path = kNoPath;
            }
        }
    }
    warpAtomicAdd(&b.counters->rays, uint32_t(counters.rays));
    warpAtomicAdd(&b.counters->nonfinite, uint32_t(counters.nonfiniteSamples));
}

}  // namespace

const void* megakernelSymbol(uint32_t variant) {
    const void* symbol = nullptr;
    forKernelVariant(variant, [&](auto features) {
        symbol = reinterpret_cast<const void*>(megakernel<decltype(features)::value>);
    });
    return symbol;
}

void launchMegakernel(uint32_t variant, const RenderScene& scene, const WaveBuffers& b,
                      const WaveShape& shape, bool regeneration, cudaStream_t stream) {
    const uint32_t blocks = (shape.pathCount + kBlock - 1) / kBlock;
    if (b.aovs.mask & kPathAovs) {  // AOVs run the generic code (kernel_variants.h)
        aovMegakernel<<<blocks, kBlock, 0, stream>>>(scene, b, shape);
        PT_CUDA_CHECK_LAUNCH("aovMegakernel");
        return;
    }
    PT_CUDA_CHECK(cudaMemsetAsync(&b.counters->claimedPaths, 0, sizeof(uint32_t), stream));
    forKernelVariant(variant, [&](auto features) {
        launchPersistent<megakernel<decltype(features)::value>, kBlock>(shape.pathCount, stream, scene, b,
                                                                        shape, regeneration);
    });
    PT_CUDA_CHECK_LAUNCH("megakernel");
}

}  // namespace pt::cuda
