// The megakernel schedule: one thread runs tracePath, the same loop the CPU backend runs, for
// one sample of one pixel.
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/warp_atomics.cuh"
#include "render/backend/cuda/wavefront_kernels.h"
#include "render/integrator/path_tracer.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kBlock = 128;

__global__ void megakernel(RenderScene scene, WaveBuffers b, WaveShape shape) {
    const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= shape.pathCount) return;
    const uint32_t pixel = i % shape.pixelCount, sample = i / shape.pixelCount;
    const uint32_t width = scene.settings.width;
    PathCounters counters;
    const Vec3 radiance = tracePath(scene, pixel % width, pixel / width, shape.firstSample + sample, counters);
    b.radiance[3 * i + 0] = radiance.x;
    b.radiance[3 * i + 1] = radiance.y;
    b.radiance[3 * i + 2] = radiance.z;
    warpAtomicAdd(&b.counters->rays, uint32_t(counters.rays));
    warpAtomicAdd(&b.counters->nonfinite, uint32_t(counters.nonfiniteSamples));
}

}  // namespace

void launchMegakernel(const RenderScene& scene, const WaveBuffers& b, const WaveShape& shape, cudaStream_t stream) {
    megakernel<<<(shape.pathCount + kBlock - 1) / kBlock, kBlock, 0, stream>>>(scene, b, shape);
    PT_CUDA_CHECK_LAUNCH("megakernel");
}

}  // namespace pt::cuda
