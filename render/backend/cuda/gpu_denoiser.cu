#include "render/backend/aov.h"
#include "render/backend/backend.h"
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/gpu_denoiser.h"
#include "render/denoise/denoiser.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kBlockSide = 16;

// The RGBA planes prepareKernel fills from the sums, one after another in GpuDenoiser::planes_.
enum Plane : uint32_t { kBeauty, kAlbedo, kNormal, kDepth, kEmission, kAlpha, kVariance, kPlaneCount };

struct Planes {
    float* base;
    uint32_t width, height;

    __host__ __device__ float* at(Plane k) const { return base + size_t(k) * 4 * width * height; }
    __host__ __device__ DenoiseGuides guides() const {
        return {width, height, at(kAlbedo), at(kNormal), at(kDepth), at(kEmission), at(kAlpha)};
    }
};

__device__ bool pixelOf(uint32_t width, uint32_t height, uint32_t& x, uint32_t& y) {
    x = blockIdx.x * blockDim.x + threadIdx.x;
    y = blockIdx.y * blockDim.y + threadIdx.y;
    return x < width && y < height;
}

__device__ void storeAov(float* plane, const AovBuffers& aovs, Aov aov, uint32_t i, uint32_t samples) {
    const uint32_t channels = aovChannels(aov);
    const double* sums = aovs.at(aov, i);
    for (uint32_t c = 0; c < 3; ++c)
        plane[4 * i + c] = aovPixelValue(aov, sums, channels == 3 ? c : 0, samples);
    plane[4 * i + 3] = 1.0f;
}

// The mean beauty and the guides as readBeauty and readAov give them, then the demodulated
// samples.
__global__ void prepareKernel(const double* sum, AovBuffers aovs, uint32_t samples, Planes p,
                              DenoiseSample* out) {
    uint32_t x, y;
    if (!pixelOf(p.width, p.height, x, y)) return;
    const uint32_t i = y * p.width + x;
    const double scale = samples ? 1.0 / samples : 0.0;
    float* beauty = p.at(kBeauty);
    for (uint32_t c = 0; c < 3; ++c) beauty[4 * i + c] = float(sum[3 * i + c] * scale);
    beauty[4 * i + 3] = 1.0f;
    storeAov(p.at(kAlbedo), aovs, Aov::Albedo, i, samples);
    storeAov(p.at(kNormal), aovs, Aov::ShadingNormal, i, samples);
    storeAov(p.at(kDepth), aovs, Aov::Depth, i, samples);
    storeAov(p.at(kEmission), aovs, Aov::Emission, i, samples);
    storeAov(p.at(kAlpha), aovs, Aov::Alpha, i, samples);
    storeAov(p.at(kVariance), aovs, Aov::Variance, i, samples);
    out[i] = denoise::demodulatedSample(beauty, p.at(kVariance), p.guides(), i);
}

// After prepareKernel: a pixel's surface reads its neighbours' depths.
__global__ void surfaceKernel(DenoiseGuides g, denoise::DenoiseSurface* out) {
    uint32_t x, y;
    if (!pixelOf(g.width, g.height, x, y)) return;
    out[y * g.width + x] = denoise::surfaceAt(g, x, y);
}

__global__ void spatialVarianceKernel(const DenoiseSample* in, const denoise::DenoiseSurface* surfaces,
                                      uint32_t width, uint32_t height, DenoiseSample* out) {
    uint32_t x, y;
    if (!pixelOf(width, height, x, y)) return;
    const uint32_t i = y * width + x;
    out[i] = {in[i].radiance, denoise::spatialVarianceAt(in, surfaces, width, height, x, y)};
}

__global__ void atrousKernel(const DenoiseSample* in, const denoise::DenoiseSurface* surfaces, uint32_t width,
                             uint32_t height, uint32_t step, DenoiseSample* out) {
    uint32_t x, y;
    if (!pixelOf(width, height, x, y)) return;
    out[y * width + x] = denoise::atrousAt(in, surfaces, width, height, x, y, step);
}

__global__ void remodulateKernel(const DenoiseSample* input, const DenoiseSample* filtered, DenoiseGuides g,
                                 uint32_t samples, float* rgba) {
    uint32_t x, y;
    if (!pixelOf(g.width, g.height, x, y)) return;
    const uint32_t i = y * g.width + x;
    const Vec3 c =
        denoise::remodulated(denoise::boundedByNoise(input[i], filtered[i].radiance, samples), g, i);
    rgba[4 * i + 0] = c.x;
    rgba[4 * i + 1] = c.y;
    rgba[4 * i + 2] = c.z;
    rgba[4 * i + 3] = 1.0f;
}

}  // namespace

void GpuDenoiser::run(const double* sum, const AovBuffers& aovs, uint32_t width, uint32_t height,
                      uint32_t samples, float* rgba, cudaStream_t stream) {
    for (const Aov guide : kDenoiseGuides) requireAov(aovs.mask, guide);
    const size_t pixels = size_t(width) * height;
    if (pixels == 0) return;
    if (planes_.size() != kPlaneCount * 4 * pixels) planes_ = DeviceBuffer<float>(kPlaneCount * 4 * pixels);
    if (a_.size() != pixels) {
        surfaces_ = DeviceBuffer<denoise::DenoiseSurface>(pixels);
        input_ = DeviceBuffer<DenoiseSample>(pixels);
        a_ = DeviceBuffer<DenoiseSample>(pixels);
        b_ = DeviceBuffer<DenoiseSample>(pixels);
    }
    const Planes p{planes_.data(), width, height};
    const dim3 block(kBlockSide, kBlockSide);
    const dim3 grid((width + kBlockSide - 1) / kBlockSide, (height + kBlockSide - 1) / kBlockSide);
    // `input` keeps each pixel's own mean and noise for boundedByNoise; the passes alternate
    // between a and b.
    DenoiseSample *input = input_.data(), *a = a_.data(), *b = b_.data();
    const bool ownVariance = samples >= kMinSamplesForOwnVariance;
    prepareKernel<<<grid, block, 0, stream>>>(sum, aovs, samples, p, ownVariance ? input : a);
    PT_CUDA_CHECK_LAUNCH("prepareKernel");
    denoise::DenoiseSurface* surfaces = surfaces_.data();
    surfaceKernel<<<grid, block, 0, stream>>>(p.guides(), surfaces);
    PT_CUDA_CHECK_LAUNCH("surfaceKernel");
    if (!ownVariance) {
        spatialVarianceKernel<<<grid, block, 0, stream>>>(a, surfaces, width, height, input);
        PT_CUDA_CHECK_LAUNCH("spatialVarianceKernel");
    }
    const DenoiseSample* from = input;
    for (uint32_t k = 0; k < kDenoiseIterations; ++k) {
        DenoiseSample* to = from == a ? b : a;
        atrousKernel<<<grid, block, 0, stream>>>(from, surfaces, width, height, 1u << k, to);
        PT_CUDA_CHECK_LAUNCH("atrousKernel");
        from = to;
    }
    remodulateKernel<<<grid, block, 0, stream>>>(input, from, p.guides(), samples, rgba);
    PT_CUDA_CHECK_LAUNCH("remodulateKernel");
}

}  // namespace pt::cuda
