#include <iterator>

#include "render/backend/aov.h"
#include "render/backend/backend.h"
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/gpu_denoiser.h"
#include "render/denoise/denoiser.h"

namespace pt::cuda {

namespace {

constexpr uint32_t kBlockSide = 16;

// The RGBA planes prepareKernel fills from the sums, one after another in GpuDenoiser::planes_:
// what the last pass multiplies and adds back.
enum Plane : uint32_t { kAlbedo, kEmission, kPlaneCount };

struct Planes {
    float* base;
    uint32_t width, height;

    __host__ __device__ float* at(Plane k) const { return base + size_t(k) * 4 * width * height; }
};

__device__ bool pixelOf(uint32_t width, uint32_t height, uint32_t& x, uint32_t& y) {
    x = blockIdx.x * blockDim.x + threadIdx.x;
    y = blockIdx.y * blockDim.y + threadIdx.y;
    return x < width && y < height;
}

// AOV `aov` of pixel i as readAov gives it (a one-channel AOV in all three).
__device__ Vec3 aovValue(const AovBuffers& aovs, Aov aov, uint32_t i, uint32_t samples) {
    const uint32_t channel = aovChannels(aov) == 3 ? 1 : 0;  // the step from one channel to the next
    const double* sums = aovs.at(aov, i);
    return {aovPixelValue(aov, sums, 0, samples), aovPixelValue(aov, sums, channel, samples),
            aovPixelValue(aov, sums, 2 * channel, samples)};
}

// Each pixel's guides from the sums (the albedo and emission kept for the last pass), its
// surface and normal stop, and the demodulated sample of its mean beauty (as readBeauty gives
// it). Only the depth slopes wait for the neighbours' surfaces (packKernel).
__global__ void prepareKernel(const double* sum, AovBuffers aovs, AovSampleCounts guideSamples,
                              uint32_t samples, Planes p, denoise::DenoiseSurface* surfaces,
                              denoise::SurfaceStops* stops, DenoiseSample* out) {
    uint32_t x, y;
    if (!pixelOf(p.width, p.height, x, y)) return;
    const uint32_t i = y * p.width + x;
    const double scale = samples ? 1.0 / samples : 0.0;
    const Vec3 beauty(float(sum[3 * i] * scale), float(sum[3 * i + 1] * scale),
                      float(sum[3 * i + 2] * scale));
    const auto guide = [&](Aov aov) { return aovValue(aovs, aov, i, guideSamples[aov]); };
    const denoise::PixelGuides pixel{guide(Aov::Albedo), guide(Aov::ShadingNormal), guide(Aov::Emission),
                                     guide(Aov::Depth).x, guide(Aov::Alpha).x};
    reinterpret_cast<float4*>(p.at(kAlbedo))[i] =
        make_float4(pixel.albedo.x, pixel.albedo.y, pixel.albedo.z, 1.0f);
    reinterpret_cast<float4*>(p.at(kEmission))[i] =
        make_float4(pixel.emission.x, pixel.emission.y, pixel.emission.z, 1.0f);
    surfaces[i] = denoise::surfaceOf(pixel, stops[i].normalPower);
    const float variance = aovPixelValue(Aov::Variance, aovs.at(Aov::Variance, i), 0, samples);
    out[i] = denoise::demodulatedSample(beauty, variance, samples, pixel);
}

// Where each pixel's own variance has too few samples: prepareKernel's samples (`in`) held to
// their firefly limits, into `out`.
__global__ void fireflyKernel(const DenoiseSample* in, const denoise::DenoiseSurface* surfaces,
                              uint32_t width, uint32_t height, DenoiseSample* out) {
    uint32_t x, y;
    if (!pixelOf(width, height, x, y)) return;
    const uint32_t i = y * width + x;
    out[i] = denoise::withoutFirefly(in[i], denoise::fireflyLimitAt(in, surfaces, width, height, x, y));
}

// The depth slopes, and the first pass's input, packed; before it, where each pixel's own
// variance has too few samples (`samples`) to stand alone, the variance its neighbours estimate
// with it (`demodulated`: fireflyKernel's output).
__global__ void packKernel(const DenoiseSample* demodulated, const denoise::DenoiseSurface* surfaces,
                           denoise::SurfaceStops* stops, uint32_t width, uint32_t height, uint32_t samples,
                           DenoiseSample* input, denoise::PackedSample* packed) {
    uint32_t x, y;
    if (!pixelOf(width, height, x, y)) return;
    const uint32_t i = y * width + x;
    stops[i].depthSlope = denoise::depthSlopeAt(surfaces, width, height, x, y);
    if (demodulated) {
        const float neighbours = denoise::fewSamplesVariance(
            denoise::spatialVarianceAt(demodulated, surfaces, stops, width, height, x, y), samples);
        input[i] = {demodulated[i].radiance,
                    denoise::firstSamplesVariance(demodulated[i].variance, neighbours, samples)};
    }
    packed[i] = denoise::packSample(input[i]);
}

// The passes take their step as a constant, so that each tap's address is the row's plus an
// offset the instruction holds. The last pass (kFinal) writes the image: the filtered value,
// held near the pixel's own mean, remodulated (`input` and `samples` are read only there).
template <uint32_t kStep, bool kFinal>
__global__ void atrousKernel(const denoise::PackedSample* in, const denoise::DenoiseSurface* surfaces,
                             const denoise::SurfaceStops* stops, Planes p, const DenoiseSample* input,
                             uint32_t samples, denoise::PackedSample* out, float* rgba) {
    uint32_t x, y;
    if (!pixelOf(p.width, p.height, x, y)) return;
    const uint32_t i = y * p.width + x;
    const denoise::PackedSample filtered =
        denoise::atrousAt(in, surfaces, stops, p.width, p.height, x, y, kStep);
    if (!kFinal) {
        out[i] = filtered;
        return;
    }
    const Vec3 radiance = denoise::filteredRadiance(input[i], filtered);
    const Vec3 c =
        denoise::remodulated(denoise::boundedByNoise(input[i], radiance, samples),
                             denoise::loadRgb(p.at(kAlbedo), i), denoise::loadRgb(p.at(kEmission), i));
    reinterpret_cast<float4*>(rgba)[i] = make_float4(c.x, c.y, c.z, 1.0f);
}

using AtrousPass = void (*)(const denoise::PackedSample*, const denoise::DenoiseSurface*,
                            const denoise::SurfaceStops*, Planes, const DenoiseSample*, uint32_t,
                            denoise::PackedSample*, float*);
// Step 2^k for pass k; the last one writes the image.
constexpr AtrousPass kAtrousPasses[] = {atrousKernel<1, false>, atrousKernel<2, false>,
                                        atrousKernel<4, false>, atrousKernel<8, false>,
                                        atrousKernel<16, true>};
static_assert(std::size(kAtrousPasses) == kDenoiseIterations, "one kernel a pass");

}  // namespace

void GpuDenoiser::run(const double* sum, const AovBuffers& aovs, const AovSampleCounts& guideSamples,
                      uint32_t width, uint32_t height, uint32_t samples, float* rgba, cudaStream_t stream) {
    for (const Aov guide : kDenoiseGuides) requireAov(aovs.mask, guide);
    const size_t pixels = size_t(width) * height;
    if (pixels == 0) return;
    if (planes_.size() != kPlaneCount * 4 * pixels) planes_ = DeviceBuffer<float>(kPlaneCount * 4 * pixels);
    if (a_.size() != pixels) {
        surfaces_ = DeviceBuffer<denoise::DenoiseSurface>(pixels);
        stops_ = DeviceBuffer<denoise::SurfaceStops>(pixels);
        input_ = DeviceBuffer<DenoiseSample>(pixels);
        demodulated_ = DeviceBuffer<DenoiseSample>();  // made when a call has too few samples
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
    if (!ownVariance && demodulated_.size() != pixels) demodulated_ = DeviceBuffer<DenoiseSample>(pixels);
    DenoiseSample* demodulated = ownVariance ? nullptr : demodulated_.data();
    denoise::DenoiseSurface* surfaces = surfaces_.data();
    denoise::SurfaceStops* stops = stops_.data();
    prepareKernel<<<grid, block, 0, stream>>>(sum, aovs, guideSamples, samples, p, surfaces, stops, input);
    PT_CUDA_CHECK_LAUNCH("prepareKernel");
    if (!ownVariance) {
        fireflyKernel<<<grid, block, 0, stream>>>(input, surfaces, width, height, demodulated);
        PT_CUDA_CHECK_LAUNCH("fireflyKernel");
    }
    packKernel<<<grid, block, 0, stream>>>(demodulated, surfaces, stops, width, height, samples, input, a);
    PT_CUDA_CHECK_LAUNCH("packKernel");
    const denoise::PackedSample* from = a;
    for (uint32_t k = 0; k < kDenoiseIterations; ++k) {
        denoise::PackedSample* to = from == a ? b : a;
        kAtrousPasses[k]<<<grid, block, 0, stream>>>(from, surfaces, stops, p, input, samples, to, rgba);
        PT_CUDA_CHECK_LAUNCH("atrousKernel");
        from = to;
    }
}

}  // namespace pt::cuda
