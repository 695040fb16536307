#pragma once
// PathScheduler: runs waves of paths on the GPU, either as wavefront stages (generate, extend,
// [sort], shade, shadow, repeated until no path is alive) or as the megakernel, and adds the
// finished samples to a per-pixel double accumulation.
#include <cuda_runtime.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "render/backend/cuda/device_buffer.h"
#include "render/backend/cuda/kernel_variants.h"
#include "render/backend/cuda/wavefront_kernels.h"

namespace pt::cuda {

struct ScheduleOptions {
    bool megakernel = false;
    bool regeneration = false;  // megakernel: a lane whose path ends takes the next at once
    bool compaction = true;
    bool materialSort = false;
    bool firstHitCache = false;  // only where camera rays repeat exactly (no jitter, no lens)
    uint32_t materialCount = 1;
    int kernelVariant = -1;  // a requested variant (kernel_variants.h); -1: the leanest covering
};

class PathScheduler {
public:
    PathScheduler();
    ~PathScheduler();
    PathScheduler(const PathScheduler&) = delete;
    PathScheduler& operator=(const PathScheduler&) = delete;

    // Forget cached camera-ray hits (the scene, camera or image size changed).
    void invalidateFirstHits() { firstHitsValid_ = false; }

    // Adds samples firstSample .. firstSample + samples - 1 of every pixel to `sum` (RGB doubles)
    // and to the AOVs of `aovs`.
    void render(const RenderScene& scene, uint32_t firstSample, uint32_t samples,
                const ScheduleOptions& options, double* sum, const AovBuffers& aovs, cudaStream_t stream);

    // Samples a pixel each wave of a render of `samples` holds (the last may hold fewer).
    uint32_t samplesPerWave(uint32_t pixelCount, uint32_t samples) const {
        const uint32_t fit = pixelCount > 0 ? maxWavePaths_ / pixelCount : 1u;
        return std::max(1u, std::min(samples, fit));
    }

    void resetCounters(cudaStream_t stream);
    RenderCounters counters() const;  // rays and non-finite samples since resetCounters; synchronises
    // Paths alive at the start of each bounce of the last wavefront wave.
    const std::vector<uint32_t>& pathsPerBounce() const { return pathsPerBounce_; }
    uint64_t bytes() const;
    // The kernel variant (kernel_variants.h) the last render ran: the leanest covering the
    // scene's features (RenderScene::features) and the AOVs.
    uint32_t variant() const { return variant_; }
    uint64_t aovBytes() const { return firstHitCosts_.bytes(); }  // within bytes()

private:
    void reserve(uint32_t pixelCount, uint32_t pathCount, const ScheduleOptions& options, bool cacheCosts);
    WaveBuffers buffers(const AovBuffers& aovs) const;
    void runWavefront(const RenderScene& scene, WaveBuffers b, const WaveShape& shape,
                      const ScheduleOptions& options, cudaStream_t stream);

    DeviceBuffer<uint4> paths_;  // SlicedArray<PathState>: kSlices planes of pathCapacity_ slices
    uint32_t pathCapacity_ = 0;
    DeviceBuffer<Hit> hits_, firstHits_;
    DeviceBuffer<TraversalStats> firstHitCosts_;  // only while bvh_cost and the first-hit cache are on
    DeviceBuffer<ShadowRay> shadows_;
    DeviceBuffer<uint32_t> queue0_, queue1_, shadowQueue_, sortKeys0_, sortKeys1_;
    DeviceBuffer<uint8_t> sortScratch_;
    DeviceBuffer<float> radiance_;
    DeviceBuffer<RenderCounters> counters_;
    BounceCounts* hostBounces_ = nullptr;  // pinned, two: the counts of the last two bounces
    cudaEvent_t bounceDone_[2] = {};       // recorded once bounce k's counts reach hostBounces_[k % 2]
    const uint32_t maxWavePaths_;          // paths a wave holds at most, from the device's memory
    uint32_t variant_ = kFullVariant;
    bool firstHitsValid_ = false;
    bool firstHitCostsValid_ = false;  // firstHitCosts_ was written with firstHits_
    uint32_t firstHitsPixels_ = 0;
    std::vector<uint32_t> pathsPerBounce_;
};

}  // namespace pt::cuda
