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

// The 7x7 windows around a block of pixels, in shared memory: the firefly limits' 48 taps a pixel
// (fireflyLimit) and the neighbours' variance's 49 (windowVariance) read them there, not through
// the L1 cache. At 1080p on the H200 (ncu, 1 spp): read through L1, the variance's loads held
// memory throughput at 91% and packKernel took 388 us at 45 registers and 52% achieved
// occupancy; from the tile, 195 us at 31 registers and 94%, bound by the taps' arithmetic (87% of
// the SMs' throughput). The whole 1-spp denoise went from 1.27 to 1.12 ms (`pt-render bench`).
// The firefly limits, two passes over their window read through L1, took 96 us at 25% of the
// issue slots, 75% of the cycles stalled on the loads; from a tile of surfaces and luminances,
// 50 us; from one 8-byte word a pixel (FireflyTile), 47 us.
static_assert(denoise::kFireflyRadius == denoise::kSpreadRadius, "one tile size serves both windows");
constexpr int kTileSide = int(kBlockSide) + 2 * denoise::kSpreadRadius;
constexpr int kTilePixels = kTileSide * kTileSide;

// Calls load(t, q, inside) for each pixel t of the block's tile: q its index in the image, where
// `inside` it; then waits for the whole block (every thread of the block takes part).
template <class Load>
__device__ void loadTile(uint32_t width, uint32_t height, const Load& load) {
    const int originX = int(blockIdx.x * blockDim.x) - denoise::kSpreadRadius;
    const int originY = int(blockIdx.y * blockDim.y) - denoise::kSpreadRadius;
    for (int t = int(threadIdx.y * blockDim.x + threadIdx.x); t < kTilePixels;
         t += int(blockDim.x * blockDim.y)) {
        const int qx = originX + t % kTileSide, qy = originY + t / kTileSide;
        const bool inside = qx >= 0 && qy >= 0 && qx < int(width) && qy < int(height);
        load(t, inside ? uint32_t(qy) * width + uint32_t(qx) : 0u, inside);
    }
    __syncthreads();
}

// The tile index of the pixel (dx, dy) from this thread's.
__device__ int tileIndex(int dx, int dy) {
    return (int(threadIdx.y) + denoise::kSpreadRadius + dy) * kTileSide + int(threadIdx.x) +
           denoise::kSpreadRadius + dx;
}

// What the firefly limits read of each pixel, one 8-byte word (the limit's two passes read the
// window twice).
struct FireflyTile {
    float2 luminance[kTilePixels];  // x: the luminance; y: 1 where it is in the window (inFireflyWindow)

    __device__ void load(const DenoiseSample* in, const denoise::DenoiseSurface* surfaces, uint32_t width,
                         uint32_t height) {
        loadTile(width, height, [&](int t, uint32_t q, bool inside) {
            const bool inWindow = inside && denoise::inFireflyWindow(in[q], surfaces[q]);
            luminance[t] =
                inWindow ? make_float2(pt::luminance(in[q].radiance), 1.0f) : make_float2(0.0f, 0.0f);
        });
    }
    // fireflyLimitAt of this thread's pixel, whose sample and surface are `own` and
    // `ownSurface`: the same sums in the same order.
    __device__ float limit(const DenoiseSample& own, const denoise::DenoiseSurface& ownSurface) const {
        if (!denoise::inFireflyWindow(own, ownSurface)) return denoise::kNoLuminanceLimit;
        return denoise::fireflyLimit([&](int dx, int dy, float& l) {
            const float2 v = luminance[tileIndex(dx, dy)];
            l = v.x;
            return v.y > 0.0f;
        });
    }
};

// What the neighbours' variance reads of each pixel.
struct SpreadTile {
    float4 surface[kTilePixels];  // DenoiseSurface: normal, depth
    float luminance[kTilePixels];
    bool included[kTilePixels];  // inside the image and not left out

    __device__ void load(const DenoiseSample* in, const denoise::DenoiseSurface* surfaces, uint32_t width,
                         uint32_t height) {
        loadTile(width, height, [&](int t, uint32_t q, bool inside) {
            const bool takesPart = inside && in[q].valid();
            const denoise::DenoiseSurface s =
                takesPart ? denoise::loadSurface(surfaces, q) : denoise::DenoiseSurface{Vec3(0.0f), 0.0f};
            surface[t] = make_float4(s.normal.x, s.normal.y, s.normal.z, s.depth);
            luminance[t] = takesPart ? pt::luminance(in[q].radiance) : 0.0f;
            included[t] = takesPart;
        });
    }
    // spatialVarianceAt of this thread's pixel, `edges` its own, the same sums in the same order.
    __device__ float variance(const denoise::EdgeStops& edges) const {
        return denoise::windowVariance(edges, [&](int dx, int dy, denoise::DenoiseSurface& s, float& l) {
            const int t = tileIndex(dx, dy);
            const float4 v = surface[t];
            s = {{v.x, v.y, v.z}, v.w};
            l = luminance[t];
            return included[t];
        });
    }
};

// Where each pixel's own variance has too few samples: prepareKernel's samples (`in`) held to
// their firefly limits, into `out`.
__global__ void fireflyKernel(const DenoiseSample* in, const denoise::DenoiseSurface* surfaces,
                              uint32_t width, uint32_t height, DenoiseSample* out) {
    __shared__ FireflyTile tile;
    tile.load(in, surfaces, width, height);  // before any thread of the block returns
    uint32_t x, y;
    if (!pixelOf(width, height, x, y)) return;
    const uint32_t i = y * width + x;
    out[i] = denoise::withoutFirefly(in[i], tile.limit(in[i], surfaces[i]));
}

// The depth slopes, and the first pass's input, packed; before it, where each pixel's own
// variance has too few samples (`kFirstSamples`: `samples` below kMinSamplesForOwnVariance) to
// stand alone, the variance its neighbours estimate with it (`demodulated`: fireflyKernel's
// output). Only that kernel holds the tile in shared memory.
template <bool kFirstSamples>
__global__ void packKernel(const DenoiseSample* demodulated, const denoise::DenoiseSurface* surfaces,
                           denoise::SurfaceStops* stops, uint32_t width, uint32_t height, uint32_t samples,
                           DenoiseSample* input, denoise::PackedSample* packed) {
    uint32_t x, y;
    const bool inside = pixelOf(width, height, x, y);
    if constexpr (kFirstSamples) {
        __shared__ SpreadTile tile;
        tile.load(demodulated, surfaces, width, height);  // before any thread of the block returns
        if (!inside) return;
        const uint32_t i = y * width + x;
        stops[i].depthSlope = denoise::depthSlopeAt(surfaces, width, height, x, y);
        const float spread = demodulated[i].valid() ? tile.variance(denoise::EdgeStops{surfaces[i], stops[i]})
                                                    : denoise::kInvalid;
        const float neighbours = denoise::fewSamplesVariance(spread, samples);
        input[i] = {demodulated[i].radiance,
                    denoise::firstSamplesVariance(demodulated[i].variance, neighbours, samples)};
    } else {
        if (!inside) return;
        stops[y * width + x].depthSlope = denoise::depthSlopeAt(surfaces, width, height, x, y);
    }
    packed[y * width + x] = denoise::packSample(input[y * width + x]);
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
    if (ownVariance) {
        packKernel<false>
            <<<grid, block, 0, stream>>>(nullptr, surfaces, stops, width, height, samples, input, a);
    } else {
        fireflyKernel<<<grid, block, 0, stream>>>(input, surfaces, width, height, demodulated);
        PT_CUDA_CHECK_LAUNCH("fireflyKernel");
        packKernel<true>
            <<<grid, block, 0, stream>>>(demodulated, surfaces, stops, width, height, samples, input, a);
    }
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
