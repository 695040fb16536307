#include "render/backend/cuda/path_scheduler.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace pt::cuda {

namespace {

// Paths in flight per wave. Every launch of a wave ends in a tail in which ever fewer threads
// run (its longest paths, each a chain of dependent BVH walks) while the rest of the GPU
// idles; a wave of several samples a pixel pays that tail once where waves of one sample pay
// it per sample. Measured on the H100 at 1080p (bench, 4 spp a call), one wave of 8.3M paths
// against four of 2.1M: Cornell box (wavefront) 321.9 vs 273.2 spp/s, Balloon (megakernel)
// 737.9 vs 408.8. A wave takes at most a sixteenth of the device memory for its wavefront
// state (kBytesPerPath): 2^23 paths, 1.8 GB, on an 80 GB H100; 2^21 on 8 GB.
// PT_MAX_WAVE_PATHS overrides the upper bound for experiments.
#ifndef PT_MAX_WAVE_PATHS
#define PT_MAX_WAVE_PATHS (1u << 23)
#endif
constexpr uint32_t kMaxWavePaths = PT_MAX_WAVE_PATHS;
constexpr uint32_t kMinWavePaths = 1u << 20;
// What a wavefront path keeps on the device: its state slices, closest hit, shadow ray, three
// queue entries, two sort keys and its finished RGB.
constexpr size_t kBytesPerPath = SlicedArray<PathState>::kSlices * sizeof(uint4) + sizeof(Hit) +
                                 sizeof(ShadowRay) + 5 * sizeof(uint32_t) + 3 * sizeof(float);

uint32_t wavePathsForDevice() {
    size_t free = 0, total = 0;
    PT_CUDA_CHECK(cudaMemGetInfo(&free, &total));
    return uint32_t(std::clamp<size_t>(total / 16 / kBytesPerPath, kMinWavePaths, kMaxWavePaths));
}

uint32_t bitsFor(uint32_t maxValue) {
    uint32_t bits = 1;
    while (bits < 32 && (maxValue >> bits) != 0) ++bits;
    return bits;
}

}  // namespace

PathScheduler::PathScheduler() : maxWavePaths_(wavePathsForDevice()) {
    PT_CUDA_CHECK(cudaMallocHost(&hostBounces_, 2 * sizeof(BounceCounts)));
    for (cudaEvent_t& e : bounceDone_) PT_CUDA_CHECK(cudaEventCreateWithFlags(&e, cudaEventDisableTiming));
    counters_.resize(1);
    counters_.fillZero();
}

PathScheduler::~PathScheduler() {
    for (cudaEvent_t e : bounceDone_) cudaEventDestroy(e);
    if (hostBounces_) cudaFreeHost(hostBounces_);
}

void PathScheduler::reserve(uint32_t pixelCount, uint32_t pathCount, const ScheduleOptions& options,
                            bool cacheCosts) {
    radiance_.resize(size_t(pathCount) * 3);
    if (!options.megakernel) {  // the megakernel keeps its paths in registers
        if (pathCapacity_ < pathCount) {
            paths_.resize(size_t(SlicedArray<PathState>::kSlices) * pathCount);
            pathCapacity_ = pathCount;
        }
        hits_.resize(pathCount);
        shadows_.resize(pathCount);
        queue0_.resize(pathCount);
        queue1_.resize(pathCount);
        shadowQueue_.resize(pathCount);
    }
    if (options.materialSort && !options.megakernel) {
        sortKeys0_.resize(pathCount);
        sortKeys1_.resize(pathCount);
        const size_t scratch = sortScratchBytes(pathCount);
        if (sortScratch_.size() < scratch) sortScratch_.resize(scratch);
    }
    if (options.firstHitCache && firstHitsPixels_ != pixelCount) {
        firstHits_.resize(pixelCount);
        firstHitsPixels_ = pixelCount;
        firstHitsValid_ = false;
    }
    // AOV memory exists only while the AOV is on: the buffer is freed, not kept, when it is off.
    if (cacheCosts && firstHitCosts_.size() != pixelCount) {
        firstHitCosts_.resize(pixelCount);
        firstHitCostsValid_ = false;
    } else if (!cacheCosts && firstHitCosts_.size() != 0) {
        firstHitCosts_ = DeviceBuffer<TraversalStats>();
        firstHitCostsValid_ = false;
    }
}

WaveBuffers PathScheduler::buffers(const AovBuffers& aovs) const {
    WaveBuffers b{};
    b.paths = {paths_.data(), pathCapacity_};
    b.hits = hits_.data();
    b.shadows = shadows_.data();
    b.queue[0] = queue0_.data();
    b.queue[1] = queue1_.data();
    b.shadowQueue = shadowQueue_.data();
    b.sortKeys[0] = sortKeys0_.data();
    b.sortKeys[1] = sortKeys1_.data();
    b.firstHits = firstHits_.data();
    b.firstHitCosts = firstHitCosts_.data();
    b.radiance = radiance_.data();
    b.counters = counters_.data();
    b.aovs = aovs;
    return b;
}

void PathScheduler::render(const RenderScene& scene, uint32_t firstSample, uint32_t samples,
                           const ScheduleOptions& options, double* sum, const AovBuffers& aovs,
                           cudaStream_t stream) {
    const uint32_t pixelCount = scene.settings.width * scene.settings.height;
    if (pixelCount == 0 || samples == 0) return;
    const uint32_t samplesPerWave = this->samplesPerWave(pixelCount, samples);
    const bool cacheCosts = options.firstHitCache && aovs.has(Aov::BvhCost);
    reserve(pixelCount, pixelCount * samplesPerWave, options, cacheCosts);
    const WaveBuffers b = buffers(aovs);
    // Chosen per render, so an edit that adds a feature runs a variant with it from its first
    // samples on. AOVs do not choose it: their code runs in kernels of its own (the megakernel's
    // AOV kernel; the wavefront's shade of camera segments), so the denoiser's guides no longer
    // put every stage of every bounce on the generic code.
    variant_ = chooseKernelVariant(scene.features, options.kernelVariant);
    for (uint32_t done = 0; done < samples;) {
        const uint32_t n = std::min(samplesPerWave, samples - done);
        const WaveShape shape{pixelCount, pixelCount * n, firstSample + done};
        if (options.megakernel) {
            launchMegakernel(variant_, scene, b, shape, options.regeneration, stream);
        } else {
            runWavefront(scene, b, shape, options, stream);
        }
        launchAccumulate(b, shape, sum, stream);
        done += n;
    }
}

// The host launches bounce k + 1 before it knows how many paths bounce k left alive: the
// stages read that count on the device (QueueLength), and the grid is sized for its bound, the
// count of bounce k - 1's survivors, which the host learns while bounce k runs. So the GPU never
// idles between bounces waiting for the host to read a count back, at the price of one empty
// bounce at the end. (Measured on an H100, the Cornell box at 1080p went from 200.0 to 201.0
// spp/s: the idle gap was smaller than bench's fixed cost of a bounce, 0.05 ms, suggested.) The
// material sort needs its count on the host (the radix sort's length), so it waits for each.
void PathScheduler::runWavefront(const RenderScene& scene, WaveBuffers b, const WaveShape& shape,
                                 const ScheduleOptions& options, cudaStream_t stream) {
    launchGeneratePaths(variant_, scene, b, shape, stream);
    // Cached hits serve bvh_cost only where their traversal work was cached with them.
    const bool cacheValid = firstHitsValid_ && (b.firstHitCosts == nullptr || firstHitCostsValid_);
    const bool cacheReads = options.firstHitCache && cacheValid;
    const bool cacheWrites = options.firstHitCache && !cacheValid;
    const uint32_t keyBits = bitsFor(options.materialCount + 1);
    const bool waitForCounts = options.materialSort;
    // Paths that bounce k leaves for bounce k + 1, as the host reads them back.
    auto survivors = [&](const BounceCounts& c) {
        return options.compaction ? c.queue : (c.alive > 0 ? shape.pathCount : 0u);
    };

    pathsPerBounce_.assign(1, shape.pathCount);
    const uint32_t* queue = nullptr;  // nullptr: every path of the wave, in order
    QueueLength length{shape.pathCount, nullptr};
    for (uint32_t k = 0;; ++k) {
        BounceCounts* out = &b.counters->bounce[k % 2];
        const bool cameraRays = k == 0;
        launchExtend(variant_, scene, b, shape, queue, length, cameraRays && cacheReads,
                     cameraRays && cacheWrites, stream);
        if (options.materialSort) {
            launchSortByMaterial(scene, b, length.bound, queue == nullptr, keyBits, sortScratch_.data(),
                                 sortScratch_.size(), stream);
            queue = b.queue[0];
        }
        PT_CUDA_CHECK(cudaMemsetAsync(out, 0, sizeof(BounceCounts), stream));
        // A camera segment goes on past bounce 0 only through surfaces that let rays through.
        const bool cameraSegments = k == 0 || scene.transparentMaterials != 0;
        launchShade(variant_, scene, b, queue, length, options.compaction, cameraSegments, out, stream);
        PT_CUDA_CHECK(
            cudaMemcpyAsync(&hostBounces_[k % 2], out, sizeof(BounceCounts), cudaMemcpyDeviceToHost, stream));
        PT_CUDA_CHECK(cudaEventRecord(bounceDone_[k % 2], stream));
        QueueLength next{length.bound, options.compaction ? &out->queue : nullptr};
        QueueLength shadows{length.bound, options.compaction ? &out->shadow : nullptr};
        if (waitForCounts) {
            PT_CUDA_CHECK(cudaEventSynchronize(bounceDone_[k % 2]));
            next = {survivors(hostBounces_[k % 2]), nullptr};
            shadows = {options.compaction ? hostBounces_[k % 2].shadow : length.bound, nullptr};
        }
        if (options.compaction) {
            launchShadow(variant_, scene, b, b.shadowQueue, shadows, false, stream);
            std::swap(b.queue[0], b.queue[1]);
            queue = b.queue[0];
        } else {
            launchShadow(variant_, scene, b, nullptr, shadows, true, stream);
            queue = nullptr;
        }
        if (waitForCounts) {
            if (next.bound == 0) break;
            pathsPerBounce_.push_back(next.bound);
        } else if (k > 0) {
            // Bounce k - 1's survivors: exactly the paths bounce k had, a bound on bounce k + 1's.
            PT_CUDA_CHECK(cudaEventSynchronize(bounceDone_[(k - 1) % 2]));
            const uint32_t bounceK = survivors(hostBounces_[(k - 1) % 2]);
            if (bounceK == 0) break;  // bounce k ran empty, and so would every later one
            pathsPerBounce_.push_back(bounceK);
            next.bound = bounceK;
        }
        length = next;
    }
    if (cacheWrites) {
        firstHitsValid_ = true;
        firstHitCostsValid_ = b.firstHitCosts != nullptr;
    }
    launchFinishPaths(b, shape, stream);
}

void PathScheduler::resetCounters(cudaStream_t stream) { counters_.fillZero(stream); }

RenderCounters PathScheduler::counters() const { return counters_.download()[0]; }

uint64_t PathScheduler::bytes() const {
    return paths_.bytes() + hits_.bytes() + firstHits_.bytes() + firstHitCosts_.bytes() + shadows_.bytes() +
           queue0_.bytes() + queue1_.bytes() + shadowQueue_.bytes() + sortKeys0_.bytes() +
           sortKeys1_.bytes() + sortScratch_.bytes() + radiance_.bytes() + counters_.bytes();
}

}  // namespace pt::cuda
