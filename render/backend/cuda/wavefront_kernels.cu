// The wavefront stages (wavefront_kernels.h): thin kernels around the shared stage functions of
// render/integrator/path_tracer.h, so both backends shade with the same code. Those that run
// per-ray code are compiled once per kernel variant (kernel_variants.h).
#include <cub/device/device_radix_sort.cuh>

#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/register_cap.cuh"
#include "render/backend/cuda/variant_dispatch.cuh"
#include "render/backend/cuda/warp_atomics.cuh"
#include "render/backend/cuda/wavefront_kernels.h"
#include "render/integrator/path_tracer.h"

namespace pt::cuda {

namespace {

// Threads a block. With the register caps held, 64 and 256 measured no better on the H100
// (render --wavefront at 1080p, spp/s, 128 / 256 / 64: Cornell 221.1 / 220.2 / 221.3, 1M-triangle
// sphere 374 / 363 / 371).
constexpr uint32_t kBlock = 128;

uint32_t blocksFor(uint32_t count) { return (count + kBlock - 1) / kBlock; }

__device__ __forceinline__ uint32_t threadIndex() { return blockIdx.x * blockDim.x + threadIdx.x; }

template <FeatureSet kF>
__global__ void generateKernel(RenderScene scene, WaveBuffers b, WaveShape shape) {
    const uint32_t i = threadIndex();
    if (i >= shape.pathCount) return;
    const uint32_t pixel = i % shape.pixelCount, sample = i / shape.pixelCount;
    const uint32_t width = scene.settings.width;
    b.paths.store(i, generatePath<kF>(scene, pixel % width, pixel / width, shape.firstSample + sample));
    b.shadows[i].valid = false;  // read in place when compaction is off
}

// kCost: the bvh_cost AOV is on, so camera segments (depth 0, also past alpha-transparent
// surfaces) count their traversal work; without, no counter exists.
// Register caps a thread (register_cap.cuh), as for the megakernel (megakernel.cu). The
// traversal kernels (extend, shadow) wait on BVH loads, and 64 registers (8 blocks of 128 an SM)
// hide that best; the shade kernel is arithmetic, and 128 (4 blocks; uncapped, the glossy and
// textured variants took 131-136 and fitted 3) suits it. Measured on the H100, render
// --wavefront at 1080p, spp/s:
//   extend and shadow uncapped / 64 / 40 registers: Cornell 209 / 216 / 201, 1M-triangle sphere
//   356 / 376 / 358, 10M 243 / 256 / 233;
//   shade uncapped / 128 / 96 registers: Cornell 201 / 202 / 191.
// The PT_*_REGISTERS macros override them for such experiments.
#ifndef PT_EXTEND_REGISTERS
#define PT_EXTEND_REGISTERS 64
#endif
#ifndef PT_SHADOW_REGISTERS
#define PT_SHADOW_REGISTERS 64
#endif
#ifndef PT_SHADE_REGISTERS
#define PT_SHADE_REGISTERS 128
#endif

template <FeatureSet kF, bool kCost>
__global__ void __launch_bounds__(kBlock, blocksPerSmFor(kBlock, PT_EXTEND_REGISTERS))
    extendKernel(RenderScene scene, WaveBuffers b, WaveShape shape, const uint32_t* queue, QueueLength length,
                 bool readCache, bool writeCache) {
    const uint32_t i = threadIndex();
    if (i >= length.value()) return;
    const uint32_t path = queue ? queue[i] : i;
    if (!queue && !PT_LOAD_MEMBER(b.paths, path, PathState, alive)) return;
    const uint32_t pixel = path % shape.pixelCount;
    const bool counted = kCost && PT_LOAD_MEMBER(b.paths, path, PathState, depth) == 0;
    Hit hit;
    TraversalStats cost;
    if (readCache) {
        hit = b.firstHits[pixel];
        if (kCost) cost = b.firstHitCosts[pixel];
    } else {
        intersectClosest<kF>(scene, PT_LOAD_MEMBER(b.paths, path, PathState, ray), hit,
                             counted ? &cost : nullptr);
        warpAtomicAdd(&b.counters->rays, 1u);
        // Every sample of a pixel shares the camera ray here, so sample 0 speaks for all.
        if (writeCache && path < shape.pixelCount) {
            b.firstHits[pixel] = hit;
            if (kCost) b.firstHitCosts[pixel] = cost;
        }
    }
    if (counted) addAovCost(b.aovs, pixel, cost);
    b.hits[path] = hit;
}

// The key of a path: 0 for a miss, else 1 + the material it hit.
// With `identity`, queue[0] is first filled with 0..count-1 (every path, in order).
__global__ void materialKeyKernel(RenderScene scene, WaveBuffers b, uint32_t count, bool identity) {
    const uint32_t i = threadIndex();
    if (i >= count) return;
    if (identity) b.queue[0][i] = i;
    const uint32_t path = b.queue[0][i];
    const Hit hit = b.hits[path];
    if (!PT_LOAD_MEMBER(b.paths, path, PathState, alive)) {
        b.sortKeys[0][i] = 0;
        return;
    }
    uint32_t key = 0;
    if (hit.valid()) {
        const RenderInstance& inst = scene.instances[hit.instance];
        const BlasRef& blas = scene.blases[inst.blas];
        const uint32_t global = blas.primitiveOffset + hit.primitive;
        const uint32_t slot =
            blas.kind == GeometryKind::Spheres ? scene.sphereSlots[global] : scene.triangleSlots[global];
        key = 1 + scene.instanceMaterials[inst.materialOffset + slot];
    }
    b.sortKeys[0][i] = key;
}

// kAovs: paths record AOVs; without, the kernel is the one that ran before AOVs existed.
template <FeatureSet kF, bool kAovs>
__global__ void __launch_bounds__(kBlock, blocksPerSmFor(kBlock, PT_SHADE_REGISTERS))
    shadeKernel(RenderScene scene, WaveBuffers b, const uint32_t* queue, QueueLength length, bool compaction,
                BounceCounts* out) {
    const uint32_t i = threadIndex();
    if (i >= length.value()) return;
    const uint32_t path = queue ? queue[i] : i;
    PathState state = b.paths.load(path);
    if (!state.alive) return;
    const Hit hit = b.hits[path];
    const bool cameraSegment = kAovs && state.depth == 0;
    AovSample aov;  // instance stays -1 unless an opaque surface is recorded
    ShadowRay shadow{};
    if (hit.valid()) {
        shadow = shadeSurface<kF>(scene, state, hit, cameraSegment ? &aov : nullptr);
    } else {
        shadeMiss<kF>(scene, state, cameraSegment ? &aov : nullptr);
    }
    // The camera segment ends at its first opaque surface or where it leaves the scene; an
    // alpha-transparent surface only moved it on, and a later shade records it.
    if (cameraSegment && (!hit.valid() || aov.instance >= 0)) {
        addAovSample(b.aovs, state.sampler.pixel, state.sampler.sampleIndex, aov);
    }
    b.paths.store(path, state);
    if (compaction) {
        if (shadow.valid) b.shadows[path] = shadow;
        warpAppend(b.shadowQueue, &out->shadow, path, shadow.valid);
        warpAppend(b.queue[1], &out->queue, path, state.alive);
    } else {
        b.shadows[path] = shadow;
        warpAtomicAdd(&out->alive, state.alive ? 1u : 0u);
    }
}

template <FeatureSet kF>
__global__ void __launch_bounds__(kBlock, blocksPerSmFor(kBlock, PT_SHADOW_REGISTERS))
    shadowKernel(RenderScene scene, WaveBuffers b, const uint32_t* queue, QueueLength length, bool consume) {
    const uint32_t i = threadIndex();
    if (i >= length.value()) return;
    const uint32_t path = queue ? queue[i] : i;
    ShadowRay shadow = b.shadows[path];
    if (!shadow.valid) return;
    if (consume) b.shadows[path].valid = false;  // in place: the next bounce starts clean
    PathCounters counters;
    const PathSampler sampler = PT_LOAD_MEMBER(b.paths, path, PathState, sampler);
    // The depth as tracePath passes it (after shading), so both schedules draw the same numbers.
    const uint32_t depth = PT_LOAD_MEMBER(b.paths, path, PathState, depth);
    if (shadowRayUnoccluded<kF>(scene, shadow, sampler, depth, counters)) {
        const Vec3 radiance = PT_LOAD_MEMBER(b.paths, path, PathState, radiance) + shadow.contribution;
        PT_STORE_MEMBER(b.paths, path, PathState, radiance, radiance);
    }
    warpAtomicAdd(&b.counters->rays, uint32_t(counters.rays));
}

__global__ void finishKernel(WaveBuffers b, WaveShape shape) {
    const uint32_t i = threadIndex();
    if (i >= shape.pathCount) return;
    Vec3 radiance = PT_LOAD_MEMBER(b.paths, i, PathState, radiance);
    const bool finite = isFinite(radiance);
    if (!finite) radiance = Vec3(0.0f);
    warpAtomicAdd(&b.counters->nonfinite, finite ? 0u : 1u);
    b.radiance[3 * i + 0] = radiance.x;
    b.radiance[3 * i + 1] = radiance.y;
    b.radiance[3 * i + 2] = radiance.z;
}

__global__ void accumulateKernel(WaveBuffers b, WaveShape shape, double* sum) {
    const uint32_t pixel = threadIndex();
    if (pixel >= shape.pixelCount) return;
    double r = sum[3 * pixel + 0], g = sum[3 * pixel + 1], bl = sum[3 * pixel + 2];
    const bool variance = b.aovs.has(Aov::Variance);
    // In sample order, one addition at a time, exactly as the CPU backend adds them.
    uint32_t sample = shape.firstSample;
    for (uint32_t path = pixel; path < shape.pathCount; path += shape.pixelCount, ++sample) {
        const Vec3 radiance(b.radiance[3 * path + 0], b.radiance[3 * path + 1], b.radiance[3 * path + 2]);
        r += double(radiance.x);
        g += double(radiance.y);
        bl += double(radiance.z);
        if (variance) addVarianceSample(b.aovs, pixel, sample, radiance);
    }
    sum[3 * pixel + 0] = r;
    sum[3 * pixel + 1] = g;
    sum[3 * pixel + 2] = bl;
}

}  // namespace

WavefrontSymbols wavefrontSymbols(uint32_t variant) {
    WavefrontSymbols s{};
    forKernelVariant(variant, [&](auto features) {
        constexpr FeatureSet kF = decltype(features)::value;
        s.extend = reinterpret_cast<const void*>(extendKernel<kF, false>);
        s.shade = reinterpret_cast<const void*>(shadeKernel<kF, false>);
        s.shadow = reinterpret_cast<const void*>(shadowKernel<kF>);
    });
    return s;
}

void launchGeneratePaths(uint32_t variant, const RenderScene& scene, const WaveBuffers& b,
                         const WaveShape& shape, cudaStream_t stream) {
    forKernelVariant(variant, [&](auto features) {
        generateKernel<decltype(features)::value>
            <<<blocksFor(shape.pathCount), kBlock, 0, stream>>>(scene, b, shape);
    });
    PT_CUDA_CHECK_LAUNCH("generateKernel");
}

void launchExtend(uint32_t variant, const RenderScene& scene, const WaveBuffers& b, const WaveShape& shape,
                  const uint32_t* queue, QueueLength length, bool readCache, bool writeCache,
                  cudaStream_t stream) {
    if (length.bound == 0) return;
    const uint32_t blocks = blocksFor(length.bound);
    if (b.aovs.has(Aov::BvhCost)) {  // AOVs run the generic code (kernel_variants.h)
        extendKernel<kAllFeatures, true>
            <<<blocks, kBlock, 0, stream>>>(scene, b, shape, queue, length, readCache, writeCache);
    } else {
        forKernelVariant(variant, [&](auto features) {
            extendKernel<decltype(features)::value, false>
                <<<blocks, kBlock, 0, stream>>>(scene, b, shape, queue, length, readCache, writeCache);
        });
    }
    PT_CUDA_CHECK_LAUNCH("extendKernel");
}

size_t sortScratchBytes(uint32_t pathCount) {
    size_t bytes = 0;
    PT_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(
        nullptr, bytes, static_cast<const uint32_t*>(nullptr), static_cast<uint32_t*>(nullptr),
        static_cast<const uint32_t*>(nullptr), static_cast<uint32_t*>(nullptr), int(pathCount)));
    return bytes;
}

void launchSortByMaterial(const RenderScene& scene, const WaveBuffers& b, uint32_t count, bool identity,
                          uint32_t keyBits, void* scratch, size_t scratchBytes, cudaStream_t stream) {
    if (count == 0) return;
    materialKeyKernel<<<blocksFor(count), kBlock, 0, stream>>>(scene, b, count, identity);
    PT_CUDA_CHECK_LAUNCH("materialKeyKernel");
    // Sorted into queue[1], then copied back: the shade stage reads queue[0].
    PT_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(scratch, scratchBytes, b.sortKeys[0], b.sortKeys[1],
                                                  b.queue[0], b.queue[1], int(count), 0, int(keyBits),
                                                  stream));
    PT_CUDA_CHECK(
        cudaMemcpyAsync(b.queue[0], b.queue[1], count * sizeof(uint32_t), cudaMemcpyDeviceToDevice, stream));
}

void launchShade(uint32_t variant, const RenderScene& scene, const WaveBuffers& b, const uint32_t* queue,
                 QueueLength length, bool compaction, bool cameraSegments, BounceCounts* out,
                 cudaStream_t stream) {
    if (length.bound == 0) return;
    const uint32_t blocks = blocksFor(length.bound);
    if (cameraSegments && (b.aovs.mask & kPathAovs)) {  // AOVs run the generic code (kernel_variants.h)
        shadeKernel<kAllFeatures, true>
            <<<blocks, kBlock, 0, stream>>>(scene, b, queue, length, compaction, out);
    } else {
        forKernelVariant(variant, [&](auto features) {
            shadeKernel<decltype(features)::value, false>
                <<<blocks, kBlock, 0, stream>>>(scene, b, queue, length, compaction, out);
        });
    }
    PT_CUDA_CHECK_LAUNCH("shadeKernel");
}

void launchShadow(uint32_t variant, const RenderScene& scene, const WaveBuffers& b, const uint32_t* queue,
                  QueueLength length, bool consume, cudaStream_t stream) {
    if (length.bound == 0) return;
    forKernelVariant(variant, [&](auto features) {
        shadowKernel<decltype(features)::value>
            <<<blocksFor(length.bound), kBlock, 0, stream>>>(scene, b, queue, length, consume);
    });
    PT_CUDA_CHECK_LAUNCH("shadowKernel");
}

void launchFinishPaths(const WaveBuffers& b, const WaveShape& shape, cudaStream_t stream) {
    finishKernel<<<blocksFor(shape.pathCount), kBlock, 0, stream>>>(b, shape);
    PT_CUDA_CHECK_LAUNCH("finishKernel");
}

void launchAccumulate(const WaveBuffers& b, const WaveShape& shape, double* sum, cudaStream_t stream) {
    accumulateKernel<<<blocksFor(shape.pixelCount), kBlock, 0, stream>>>(b, shape, sum);
    PT_CUDA_CHECK_LAUNCH("accumulateKernel");
}

}  // namespace pt::cuda
