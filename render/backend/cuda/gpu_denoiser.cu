#include "render/backend/aov.h"
#include "render/backend/backend.h"
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/gpu_denoiser.h"
#include "render/denoise/denoiser.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kBlockSide = 16;

// The RGBA planes prepareKernel fills from the sums, one after another in GpuDenoiser::planes_.
enum Plane : uint32_t { kAlbedo, kNormal, kDepth, kEmission, kAlpha, kPlaneCount };

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

// The guides as readAov gives them, then the demodulated samples of the mean beauty (as
// readBeauty gives it).
__global__ void prepareKernel(const double* sum, AovBuffers aovs, uint32_t samples, Planes p,
                              DenoiseSample* out) {
    uint32_t x, y;
    if (!pixelOf(p.width, p.height, x, y)) return;
    const uint32_t i = y * p.width + x;
    const double scale = samples ? 1.0 / samples : 0.0;
    const Vec3 beauty(float(sum[3 * i] * scale), float(sum[3 * i + 1] * scale),
                      float(sum[3 * i + 2] * scale));
    storeAov(p.at(kAlbedo), aovs, Aov::Albedo, i, samples);
    storeAov(p.at(kNormal), aovs, Aov::ShadingNormal, i, samples);
    storeAov(p.at(kDepth), aovs, Aov::Depth, i, samples);
    storeAov(p.at(kEmission), aovs, Aov::Emission, i, samples);
    storeAov(p.at(kAlpha), aovs, Aov::Alpha, i, samples);
    const float variance = aovPixelValue(Aov::Variance, aovs.at(Aov::Variance, i), 0, samples);
    out[i] = denoise::demodulatedSample(beauty, variance, samples, p.guides(), i);
}

// After prepareKernel: a pixel's surface reads its neighbours' depths.
__global__ void surfaceKernel(DenoiseGuides g, denoise::DenoiseSurface* surfaces,
                              denoise::SurfaceStops* stops) {
    uint32_t x, y;
    if (!pixelOf(g.width, g.height, x, y)) return;
    const uint32_t i = y * g.width + x;
    surfaces[i] = denoise::surfaceAt(g, x, y, stops[i]);
}

// The first passes' input, packed; before it, where each pixel's own variance has too few
// samples, the variance its neighbours estimate (`demodulated`: prepareKernel's output).
__global__ void packKernel(const DenoiseSample* demodulated, const denoise::DenoiseSurface* surfaces,
                           const denoise::SurfaceStops* stops, uint32_t width, uint32_t height,
                           DenoiseSample* input, denoise::PackedSample* packed) {
    uint32_t x, y;
    if (!pixelOf(width, height, x, y)) return;
    const uint32_t i = y * width + x;
    if (demodulated) {
        input[i] = {demodulated[i].radiance,
                    denoise::spatialVarianceAt(demodulated, surfaces, stops, width, height, x, y)};
    }
    packed[i] = denoise::packSample(input[i]);
}

__global__ void atrousKernel(const denoise::PackedSample* in, const denoise::DenoiseSurface* surfaces,
                             const denoise::SurfaceStops* stops, uint32_t width, uint32_t height,
                             uint32_t step, denoise::PackedSample* out) {
    uint32_t x, y;
    if (!pixelOf(width, height, x, y)) return;
    out[y * width + x] = denoise::atrousAt(in, surfaces, stops, width, height, x, y, step);
}

__global__ void remodulateKernel(const DenoiseSample* input, const denoise::PackedSample* filtered,
                                 DenoiseGuides g, uint32_t samples, float* rgba) {
    uint32_t x, y;
    if (!pixelOf(g.width, g.height, x, y)) return;
    const uint32_t i = y * g.width + x;
    const Vec3 radiance = denoise::filteredRadiance(input[i], filtered[i]);
    const Vec3 c = denoise::remodulated(denoise::boundedByNoise(input[i], radiance, samples), g, i);
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
        stops_ = DeviceBuffer<denoise::SurfaceStops>(pixels);
        input_ = DeviceBuffer<DenoiseSample>(pixels);
        demodulated_ = DeviceBuffer<DenoiseSample>(pixels);
        a_ = DeviceBuffer<denoise::PackedSample>(pixels);
        b_ = DeviceBuffer<denoise::PackedSample>(pixels);
    }
    const Planes p{planes_.data(), width, height};
    const dim3 block(kBlockSide, kBlockSide);
    const dim3 grid((width + kBlockSide - 1) / kBlockSide, (height + kBlockSide - 1) / kBlockSide);
    // `input` keeps each pixel's own mean and noise for boundedByNoise; the passes alternate
    // between a and b.
    DenoiseSample* input = input_.data();
    denoise::PackedSample *a = a_.data(), *b = b_.data();
    const bool ownVariance = samples >= kMinSamplesForOwnVariance;
    DenoiseSample* demodulated = ownVariance ? nullptr : demodulated_.data();
    prepareKernel<<<grid, block, 0, stream>>>(sum, aovs, samples, p, ownVariance ? input : demodulated);
    PT_CUDA_CHECK_LAUNCH("prepareKernel");
    denoise::DenoiseSurface* surfaces = surfaces_.data();
    denoise::SurfaceStops* stops = stops_.data();
    surfaceKernel<<<grid, block, 0, stream>>>(p.guides(), surfaces, stops);
    PT_CUDA_CHECK_LAUNCH("surfaceKernel");
    packKernel<<<grid, block, 0, stream>>>(demodulated, surfaces, stops, width, height, input, a);
    PT_CUDA_CHECK_LAUNCH("packKernel");
    const denoise::PackedSample* from = a;
    for (uint32_t k = 0; k < kDenoiseIterations; ++k) {
        denoise::PackedSample* to = from == a ? b : a;
        atrousKernel<<<grid, block, 0, stream>>>(from, surfaces, stops, width, height, 1u << k, to);
        PT_CUDA_CHECK_LAUNCH("atrousKernel");
        from = to;
    }
    remodulateKernel<<<grid, block, 0, stream>>>(input, from, p.guides(), samples, rgba);
    PT_CUDA_CHECK_LAUNCH("remodulateKernel");
}

}  // namespace pt::cuda
