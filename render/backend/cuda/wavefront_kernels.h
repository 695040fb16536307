#pragma once
// The stages of the wavefront path tracer as host-callable launches (the kernels live in
// wavefront_kernels.cu). One wave holds `pathCount` paths: sample s of pixel p is path
// s * pixelCount + p. Between stages the paths live in device arrays (PathState, Hit,
// ShadowRay per path) and the stages pass work on through index queues.
#include <cuda_runtime.h>

#include <cstdint>

#include "render/backend/cuda/sliced_array.cuh"
#include "render/backend/cuda/work_claims.h"
#include "render/bvh/hit.h"
#include "render/integrator/aov.h"
#include "render/integrator/path_state.h"
#include "render/kernel/render_scene.h"

namespace pt::cuda {

// What one wavefront bounce's shade stage counts on the device.
struct BounceCounts {
    uint32_t queue;   // paths appended to the next bounce's queue (compaction)
    uint32_t shadow;  // shadow rays appended to the shadow queue (compaction)
    uint32_t alive;   // without compaction: paths still alive
    uint32_t pad;
};

// Device counters of a render, summed over kernels.
struct RenderCounters {
    unsigned long long rays;       // closest-hit and shadow rays traced
    unsigned long long nonfinite;  // samples dropped for NaN or Inf
    // Wavefront: bounce k counts into bounce[k % 2] while bounce k + 1's stages read how many
    // paths they have from it, so the host need not wait for a count before it launches them.
    BounceCounts bounce[2];
    // Megakernel: paths of the wave handed out so far (launchMegakernel zeroes it).
    uint32_t claimedPaths;
    uint32_t pad;
};

// How many entries of a queue a stage processes: at most `bound`, which the host knows and
// sizes the grid for, and exactly *exact where the count is only known on the device (written
// by an earlier stage in the same stream; nullptr: bound is exact). Threads past the count
// return at once.
struct QueueLength {
    uint32_t bound;
    const uint32_t* exact;

    __device__ uint32_t value() const { return exact ? *exact : bound; }
};

struct WaveBuffers {
    SlicedArray<PathState> paths;  // structure of 16-byte slices (sliced_array.cuh)
    Hit* hits;
    ShadowRay* shadows;
    uint32_t* queue[2];  // this bounce's paths, the next bounce's
    uint32_t* shadowQueue;
    uint32_t* sortKeys[2];          // material sort: keys in, keys out
    Hit* firstHits;                 // first-hit cache, one per pixel (nullptr: no cache)
    TraversalStats* firstHitCosts;  // their traversal work, for bvh_cost (nullptr: not needed)
    float* radiance;                // RGB per path: the finished samples of the wave
    RenderCounters* counters;
    AovBuffers aovs;  // per-pixel AOV sums (mask 0: none)
};

struct WaveShape {
    uint32_t pixelCount;
    uint32_t pathCount;  // pixelCount x samples in the wave
    uint32_t firstSample;
};

// `variant` (every launcher of per-ray code takes one): the kernel variant to run
// (kernel_variants.h), chosen by the scheduler from the scene's features; with AOVs on, the
// stages that record them run the generic variant whatever this says.
void launchGeneratePaths(uint32_t variant, const RenderScene& scene, const WaveBuffers& b,
                         const WaveShape& shape, cudaStream_t stream);

// Closest hits of the paths in `queue` (`length` entries; all paths when queue is nullptr).
// readCache: camera rays whose hits are in b.firstHits; writeCache: store them there. With the
// bvh_cost AOV, camera segments count their traversal work into it.
void launchExtend(uint32_t variant, const RenderScene& scene, const WaveBuffers& b, const WaveShape& shape,
                  const uint32_t* queue, QueueLength length, bool readCache, bool writeCache,
                  cudaStream_t stream);

// Material sort: reorders queue[0] (count entries; with `identity` first set to every path) by
// the material each path hit, misses and dead paths first, through queue[1] and sortKeys.
// `scratch` must hold sortScratchBytes(pathCount) bytes.
size_t sortScratchBytes(uint32_t pathCount);
void launchSortByMaterial(const RenderScene& scene, const WaveBuffers& b, uint32_t count, bool identity,
                          uint32_t keyBits, void* scratch, size_t scratchBytes, cudaStream_t stream);

// Shading of the paths in `queue` (`length` entries; all paths when nullptr). With compaction,
// live paths are appended to b.queue[1] and valid shadow rays to b.shadowQueue, counted in
// `out` (device memory, zeroed by the caller); without, shadows are marked valid in place and
// out->alive counts the live paths. Camera segments that end here add their AOVs to b.aovs:
// `cameraSegments` says whether any may be among the paths (else the variant's kernel, which
// has no AOV code, runs).
void launchShade(uint32_t variant, const RenderScene& scene, const WaveBuffers& b, const uint32_t* queue,
                 QueueLength length, bool compaction, bool cameraSegments, BounceCounts* out,
                 cudaStream_t stream);

// Shadow rays of the paths in `queue` (`length` entries; all paths when nullptr); invalid ones
// are skipped, and unoccluded contributions are added to the paths' radiance. `consume` marks
// each one invalid once traced (in-place shadow rays, compaction off).
void launchShadow(uint32_t variant, const RenderScene& scene, const WaveBuffers& b, const uint32_t* queue,
                  QueueLength length, bool consume, cudaStream_t stream);

// Finished paths' radiance into b.radiance, non-finite samples counted and zeroed.
void launchFinishPaths(const WaveBuffers& b, const WaveShape& shape, cudaStream_t stream);

// The megakernel: each thread traces whole paths (tracePath) into b.radiance, and their AOVs
// into b.aovs. With `regeneration` (and no path AOVs), a thread whose path ends takes the next
// path of the wave at once, so its warp keeps all its lanes busy (megakernel.cu); without, a
// warp takes new paths only when all 32 of its paths have ended.
void launchMegakernel(uint32_t variant, const RenderScene& scene, const WaveBuffers& b,
                      const WaveShape& shape, bool regeneration, cudaStream_t stream);

// The kernels of a variant without AOVs, for their resources (kernel_variants.h).
struct WavefrontSymbols {
    const void* extend;
    const void* shade;
    const void* shadow;
};
WavefrontSymbols wavefrontSymbols(uint32_t variant);
const void* megakernelSymbol(uint32_t variant);

// Traversal alone (Backend::traceRays): closest hits, or with anyHit occlusion as instance 0 /
// Hit::kNoHit, of `count` world-space rays, on a persistent grid that hands the rays out with
// `claims` (persistent_grid.cuh).
void launchTraceRays(const RenderScene& scene, const Ray* rays, uint32_t count, bool anyHit, Hit* hits,
                     WorkClaims* claims, cudaStream_t stream);

// Adds the wave's samples to the per-pixel double sums (RGB), samples of a pixel in order, and
// to the variance AOV where it is on.
void launchAccumulate(const WaveBuffers& b, const WaveShape& shape, double* sum, cudaStream_t stream);

}  // namespace pt::cuda
