#pragma once
// The denoiser (render/denoise/) on the GPU: the same per-pixel steps as denoiseOnCpu, each a
// kernel, over guides computed from the accumulation's sums where they are, so neither the
// guides nor the image leave the device. Its working memory exists only once it has run.
#include <cuda_runtime.h>

#include <cstdint>

#include "render/backend/aov.h"
#include "render/backend/cuda/device_buffer.h"
#include "render/denoise/atrous_filter.h"

namespace pt::cuda {

class GpuDenoiser {
public:
    // The mean of `sum` (RGB doubles a pixel over `samples`) denoised into `rgba` (device, RGBA
    // float a pixel), guided by the AOV sums of `aovs`, which must hold kDenoiseGuideAovs
    // (backend.h), each over its `guideSamples` (fewer than `samples` where capped).
    void run(const double* sum, const AovBuffers& aovs, const AovSampleCounts& guideSamples, uint32_t width,
             uint32_t height, uint32_t samples, float* rgba, cudaStream_t stream);
    uint64_t bytes() const {
        return planes_.bytes() + surfaces_.bytes() + stops_.bytes() + input_.bytes() + demodulated_.bytes() +
               a_.bytes() + b_.bytes();
    }

private:
    DeviceBuffer<float> planes_;  // the guides the last pass reads back, albedo and emission: RGBA
    DeviceBuffer<denoise::DenoiseSurface> surfaces_;  // each pixel's surface for the edge stops
    DeviceBuffer<denoise::SurfaceStops> stops_;       // and what only its own stops read
    // The demodulated input (at few samples, its fireflies held down in `demodulated_`, whose
    // neighbours then estimate its variance), and the passes' two packed planes.
    DeviceBuffer<DenoiseSample> input_, demodulated_;
    DeviceBuffer<denoise::PackedSample> a_, b_;
};

}  // namespace pt::cuda
