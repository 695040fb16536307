#pragma once
// The beauty as the viewport shows it, computed on the GPU: per-pixel double sums divided into
// mean RGBA float (A = 1), written straight into device memory the caller owns (the editor's
// OpenGL pixel buffer, mapped through CUDA-GL interop), so a frame never crosses to the host.
// The same arithmetic as meanImageFromSums (render/backend/mean_image.h): a product with
// 1/samples in double, rounded once to float.
#include <cuda_runtime.h>

#include <cstddef>
#include <cstdint>

namespace pt::cuda {

void launchMeanToRgba(const double* sums, size_t pixels, uint32_t samples, float* rgba, cudaStream_t stream);

}  // namespace pt::cuda
