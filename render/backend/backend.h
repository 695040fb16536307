#pragma once
// Backend: the one interface the CLI and the editor know a renderer by (STYLE.md rule 4).
// A backend owns its copy of the compiled scene and a progressive accumulation of linear
// radiance; sync() brings the copy up to date after an edit, render() adds samples.
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/backend/aov.h"
#include "render/backend/device_bvh_figures.h"
#include "render/backend/kernel_figures.h"
#include "render/backend/toggle_table.h"
#include "render/bvh/hit.h"
#include "render/compile/scene_features.h"
#include "render/math/ray.h"
#include "render/scene/scene.h"
#include "render/scene/scene_animation.h"
#include "render/scene/scene_changes.h"
#include "render/util/progress.h"

namespace pt {

// One toggle as the active backend applies it: `active` is false where it is on but cannot
// apply here (e.g. the first-hit cache under pixel jitter), and `note` says why.
struct ToggleState {
    ToggleId id;
    std::string name;  // the toggle table's key (render/backend/toggle_table.h)
    bool requested = false;
    bool active = false;
    std::string note;
};

struct SyncStep {
    std::string name;  // e.g. "upload", "refit BLAS", "rebuild BLAS", "build TLAS"
    double seconds = 0.0;
};

struct SyncReport {
    // What sync did, the most expensive first: "full build", "rebuild", "refit", "TLAS",
    // "materials", "lights", "reset" or "nothing".
    std::string action;
    double seconds = 0.0;
    double bvhSeconds = 0.0;      // BLAS + TLAS build time within `seconds`
    std::vector<SyncStep> steps;  // what each part cost
};

struct BackendStats {
    uint32_t samplesPerPixel = 0;
    double renderSeconds = 0.0;     // time spent in render() since the last reset
    uint64_t rays = 0;              // closest-hit and shadow rays since the last reset
    uint64_t nonfiniteSamples = 0;  // NaN/Inf samples dropped since the last reset
    uint64_t triangles = 0;         // traced (over instances)
    uint32_t instances = 0;
    // What the scene uses (render/compile/scene_features.h), with the AOVs and brute-force bits
    // this backend's outputs and toggles add; recomputed at every sync.
    FeatureSet features = 0;
    // GPU backends: the kernel variant that runs (render/backend/cuda/kernel_variants.h) and the
    // features it was compiled for; "" and 0 where code is not specialised (the CPU).
    std::string kernelVariant = "";
    uint32_t kernelFeatures = 0;
    // GPU backends: the schedule that runs ("megakernel", "wavefront", or "measuring" while the
    // auto schedule times both) and, under auto, the rates it measured (spp/s; 0: not yet).
    std::string schedule;
    double megakernelRate = 0.0, wavefrontRate = 0.0;
    // GPU backends with compressed 8-wide BLASes: the walk that runs ("compressed" or "binary",
    // as the auto schedule's trial decided; "" while it measures, and where there are none).
    std::string walk;
};

// What a backend can do, for front ends that show, time or report what applies to it (rather
// than testing its name).
struct BackendCapabilities {
    // It schedules paths on a GPU: the toggle table's GpuScheduling rows and kernel variants
    // apply, and its timings exclude the copy to the host.
    bool gpuScheduling = false;
    // copyBeautyToDevice() can fill device memory: frames may reach the screen through interop.
    bool deviceFrames = false;
    // It skins meshes on its device from the joint matrices a pose leaves pending
    // (SkinningSite::Device, render/scene/scene_animation.h). A backend without it reads the
    // Scene's vertices: pose with SkinningSite::Host, or skinPendingOnHost before its sync.
    bool skinsOnDevice = false;
};

class Backend {
public:
    virtual ~Backend() = default;
    virtual std::string name() const = 0;  // for display and reports: "cpu", "cuda"
    virtual BackendCapabilities capabilities() const { return {}; }
    virtual std::string deviceName() const { return "CPU"; }  // what it runs on, for reports

    // Throws std::invalid_argument when the scene or toggles cannot be honoured; the previous
    // state is then kept.
    virtual SyncReport sync(const Scene& scene, const SceneDelta& changes,
                            const ProgressFn& progress = {}) = 0;
    virtual void setToggles(const IntegratorToggles& toggles) = 0;  // takes effect at next sync
    virtual void render(uint32_t passes) = 0;                       // adds `passes` samples per pixel
    // Waits for work the last sync left running behind the first frame (the CUDA backend's host
    // SAH builds of large meshes, IntegratorToggles::gpuFirstBuild) and puts it to use; returns
    // the seconds that took, or nothing where no work was left. Nothing needs it: render() takes
    // up finished work by itself.
    virtual std::optional<double> finishBackgroundWork() { return std::nullopt; }
    // A flag another thread raises to stop a render() under way (the editor: an edit that
    // restarts the accumulation has arrived, so the samples in flight are wasted). While it is
    // up, render() stops before its next sample (CPU) or wave (GPU), resets the accumulation (a
    // pass that reached only some pixels is no sample) and returns. Null, the default: never.
    // (Virtual for backends that wrap another.)
    virtual void setInterruptFlag(const std::atomic<bool>* flag) { interrupt_ = flag; }
    virtual void resetAccumulation() = 0;

    virtual uint32_t width() const = 0;
    virtual uint32_t height() const = 0;
    // Mean linear radiance, RGBA float (A = 1), row-major, top row first.
    virtual void readBeauty(std::vector<float>& rgba) const = 0;
    virtual BackendStats stats() const = 0;
    virtual std::vector<ToggleState> toggleStates() const = 0;

    // Traversal alone, for benchmarks and picking: the closest hit (or, with anyHit, whether
    // anything is hit: Hit::instance 0 or kNoHit) of each world-space ray, traced `runs`
    // times over rays already in the backend's memory. Returns each run's seconds; `hits`
    // (may be null) receives the last run's results.
    virtual std::vector<double> traceRays(const std::vector<Ray>& rays, bool anyHit, uint32_t runs,
                                          std::vector<Hit>* hits) = 0;
    // The Scene::instances index of a hit's instance (Hit::instance), as of the last sync;
    // -1 where there is none.
    virtual int32_t sceneInstance(uint32_t hitInstance) const = 0;
    virtual uint64_t deviceMemoryBytes() const { return 0; }  // GPU backends: buffers allocated
    // GPU backends: every device buffer's allocated bytes by name (geometry, BVHs, materials,
    // lights, accumulation, scheduler, scratch), summing to deviceMemoryBytes(); empty elsewhere.
    virtual std::vector<std::pair<std::string, uint64_t>> deviceMemoryByBuffer() const { return {}; }
    // Wavefront schedulers: the paths alive at the start of each bounce of the last wave (what
    // stream compaction keeps the GPU busy with); empty where paths are not queued.
    virtual std::vector<uint32_t> pathsAlivePerBounce() const { return {}; }
    // GPU backends: writes the beauty as readBeauty() gives it (RGBA float, width x height) into
    // device memory at `deviceRgba` (e.g. an OpenGL buffer mapped through CUDA-GL interop) and
    // returns true once it is there. False where frames live on the host.
    virtual bool copyBeautyToDevice(void* deviceRgba) const {
        (void)deviceRgba;
        return false;
    }
    // GPU backends: device memory for one RGBA float frame of the current size, freed with the
    // returned object, for timing the device frame path where no display is (pt-render bench);
    // null where frames live on the host.
    virtual std::shared_ptr<void> allocateDeviceFrame() const { return nullptr; }
    // GPU backends: the device BVH builders timed on `input` (device_bvh_figures.h); nothing
    // where the backend builds no BVH on a device.
    // GPU backends: the kernel variants compiled and each kernel's resources (kernel_figures.h).
    virtual KernelFigures kernelFigures() const { return {}; }
    virtual std::optional<DeviceBvhFigures> measureDeviceBvh(const BvhBuildInput& input, uint32_t runs) {
        (void)input, (void)runs;
        return std::nullopt;
    }

    // AOVs (render/integrator/aov.h says what each holds). setAovs chooses which to accumulate
    // beside the beauty; the choice applies from the next accumulation reset (resetAccumulation,
    // setToggles, or a sync that resets), and only the AOVs it names then have memory. The
    // beauty is the same with or without them.
    virtual void setAovs(AovMask aovs) = 0;
    // Changes the AOVs accumulated now without touching the beauty (the editor's AOV view and
    // export layers are display changes): the AOVs kept keep their sums, new ones start at the
    // next pass and average over their own samples (aovSamples), the ones left out are freed.
    // It is also setAovs' choice: the next reset starts them all with the beauty again.
    virtual void changeAovs(AovMask aovs) = 0;
    // The AOVs accumulated now: the last setAovs once a reset has applied it (0 before), or the
    // last changeAovs.
    virtual AovMask aovs() const = 0;
    // The samples AOV `aov` holds: stats().samplesPerPixel, less the samples taken before
    // changeAovs added it and those it skipped under the sample cap.
    virtual uint32_t aovSamples(Aov aov) const = 0;
    // From the next pass on, the path AOVs in `cap.aovs` stop accumulating once they hold
    // `cap.samples` samples, keeping their average (an AOV the cap no longer holds goes on); it
    // outlives resets. For the denoiser's guides (kSettledGuideSamples); throws
    // std::invalid_argument as checkAovSampleCap does.
    // Virtual so that a backend wrapping another hands both on.
    virtual void setAovSampleCap(const AovSampleCap& cap) {
        checkAovSampleCap(cap);
        aovSampleCap_ = cap;
    }
    virtual AovSampleCap aovSampleCap() const { return aovSampleCap_; }
    // Per-pixel value of an AOV, RGBA float, row-major top row first, same size as the beauty.
    // Throws std::invalid_argument when that AOV is not enabled (not in aovs()).
    virtual void readAov(Aov aov, std::vector<float>& rgba) const = 0;
    // Memory the AOVs hold now (host memory on the CPU, device memory on a GPU); 0 without AOVs.
    virtual uint64_t aovBytes() const = 0;

    // The beauty denoised (render/denoise/), RGBA float like readBeauty; returns the seconds the
    // filter took (on a GPU its kernels, without the copy to the host). Needs the guides
    // (kDenoiseGuideAovs) among aovs(), each holding every sample of the beauty (since a reset)
    // or at least the sample cap's (denoiseGuidesComplete); throws std::invalid_argument naming
    // one missing. This default reads them back and
    // filters on the CPU.
    virtual double readDenoised(std::vector<float>& rgba) const;
    // The same into device memory (CUDA-GL interop), the filter's seconds in *seconds; false
    // where the backend has no device.
    virtual bool copyDenoisedToDevice(void* deviceRgba, double* seconds) const {
        (void)deviceRgba, (void)seconds;
        return false;
    }

protected:
    bool interruptRequested() const { return interrupt_ && interrupt_->load(std::memory_order_relaxed); }

private:
    const std::atomic<bool>* interrupt_ = nullptr;
    AovSampleCap aovSampleCap_;
};

// The AOVs the denoiser reads: first-hit albedo, shading normal, depth and emission, and the
// variance of each pixel's mean.
constexpr Aov kDenoiseGuides[] = {Aov::Albedo,   Aov::ShadingNormal, Aov::Depth,
                                  Aov::Emission, Aov::Alpha,         Aov::Variance};
template <size_t N>
constexpr AovMask aovMaskOf(const Aov (&aovs)[N]) {
    AovMask mask = 0;
    for (const Aov a : aovs) mask |= aovBit(a);
    return mask;
}
constexpr AovMask kDenoiseGuideAovs = aovMaskOf(kDenoiseGuides);
// How many samples the denoiser's guides take (their cap in the editor and pt-render), while
// recording them keeps the path tracer on its generic AOV kernel: with 256 (and with 64) the
// denoised image's error at equal time matched the raw one's after 3 s, where guides of every
// sample left 1.09-1.14x it (`pt-render converge`, H200; README has the figures).
constexpr uint32_t kSettledGuideSamples = 256;
// The cap a front end sets: the guides the path records (all but the variance, which follows
// the beauty) at `samples`, less those `kept` names (an AOV the user views or exports
// accumulates in full); `samples` 0: no cap.
AovSampleCap settledGuideCap(AovMask kept = 0, uint32_t samples = kSettledGuideSamples);
// readDenoised's condition: `backend` accumulates every guide, each holding all the beauty's
// samples (none added later by changeAovs) or at least the cap's samples (whether or not the
// cap covers it now). requireDenoiseGuides
// throws std::invalid_argument naming the guide that fails it.
bool denoiseGuidesComplete(const Backend& backend);
void requireDenoiseGuides(const Backend& backend);

// "cpu", or "cuda" where built. Throws std::invalid_argument naming the backends available,
// or, for "cuda" on a machine without a usable GPU, saying why.
std::unique_ptr<Backend> createBackend(const std::string& name);
// Where a front end poses skinned meshes for `backend`: on its device where it skins there.
inline SkinningSite skinningSite(const Backend& backend) {
    return backend.capabilities().skinsOnDevice ? SkinningSite::Device : SkinningSite::Host;
}

// The backend a front end opens when the user names none: "cuda" where this build has it and
// a usable GPU is present, else "cpu".
std::string defaultBackendName();

}  // namespace pt
