#pragma once
// The denoiser on the CPU: the a-trous filter of atrous_filter.h over a whole image, one TBB
// task per row band for each of its passes. The CUDA backend runs the same per-pixel steps as
// kernels.
#include <cstdint>
#include <memory>
#include <vector>

#include "render/denoise/atrous_filter.h"

namespace pt {

// Five a-trous passes (taps 1 to 16 pixels apart): a 125-pixel-wide footprint at 1080p.
constexpr uint32_t kDenoiseIterations = 5;
// Below this many samples a pixel, each pixel's own variance estimate has too few samples to
// stand alone: fireflies are first held to their neighbours (fireflyLimitAt), whose spread then
// gives the variance (spatialVarianceAt), alone at 1 spp and in a geometric mean with the
// pixel's own from 2 (firstSamplesVariance).
constexpr uint32_t kMinSamplesForOwnVariance = 4;

struct DenoiseInput {
    uint32_t samples = 0;                   // of the accumulation, a pixel
    const float* beauty = nullptr;          // mean radiance, RGBA
    const float* varianceOfMean = nullptr;  // the variance AOV (r: variance of the mean luminance)
    DenoiseGuides guides{};                 // size and guide planes (atrous_filter.h)
};

// The denoiser on the CPU, keeping its working memory for the next call of the same size.
class CpuDenoiser {
public:
    CpuDenoiser();
    ~CpuDenoiser();
    // The denoised beauty, RGBA (alpha 1), finite everywhere.
    void run(const DenoiseInput& in, std::vector<float>& rgba);

private:
    struct Workspace;
    std::unique_ptr<Workspace> workspace_;
};

// One denoise, its working memory freed after.
void denoiseOnCpu(const DenoiseInput& in, std::vector<float>& rgba);

}  // namespace pt
