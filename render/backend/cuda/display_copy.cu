#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/display_copy.h"

namespace pt::cuda {
namespace {

__global__ void meanToRgba(const double* sums, size_t pixels, double scale, float* rgba) {
    const size_t i = size_t(blockIdx.x) * blockDim.x + threadIdx.x;
    if (i >= pixels) return;
    rgba[i * 4 + 0] = float(sums[i * 3 + 0] * scale);
    rgba[i * 4 + 1] = float(sums[i * 3 + 1] * scale);
    rgba[i * 4 + 2] = float(sums[i * 3 + 2] * scale);
    rgba[i * 4 + 3] = 1.0f;
}

}  // namespace

void launchMeanToRgba(const double* sums, size_t pixels, uint32_t samples, float* rgba, cudaStream_t stream) {
    if (pixels == 0) return;
    const double scale = samples ? 1.0 / samples : 0.0;
    constexpr unsigned kBlock = 256;
    meanToRgba<<<unsigned((pixels + kBlock - 1) / kBlock), kBlock, 0, stream>>>(sums, pixels, scale, rgba);
    PT_CUDA_CHECK_LAUNCH("meanToRgba");
}

}  // namespace pt::cuda
