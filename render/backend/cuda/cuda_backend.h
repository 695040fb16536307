#pragma once
// CudaBackend: the shared per-ray code on the GPU, scheduled as a wavefront (or a megakernel,
// a toggle), accumulating in double per pixel like the CPU backend so both give the same sums.
// sync() does the least work an edit needs (DESIGN.md, "Data flow"): nothing, a reset, new
// materials or lights, a TLAS rebuilt on the GPU, a BLAS refit on the GPU (rebuilt there
// with an LBVH once refits have degraded its SAH cost past a ratio), or a full compile on the
// host for new meshes and textures, whose binned SAH BLASes are uploaded. Edits cost what
// they change: a transform costs the host O(instances) (never a walk over triangles), a
// vertex edit uploads the range of vertices that changed.
#include <cuda_runtime.h>

#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/backend/backend.h"
#include "render/backend/cuda/device_scene.h"
#include "render/backend/cuda/device_skins.h"
#include "render/backend/cuda/gpu_bvh.h"
#include "render/backend/cuda/gpu_denoiser.h"
#include "render/backend/cuda/path_scheduler.h"
#include "render/backend/cuda/pinned_range.h"
#include "render/backend/cuda/work_claims.h"
#include "render/backend/schedule_chooser.h"
#include "render/backend/sync_steps.h"
#include "render/bvh/background_bvh_build.h"
#include "render/compile/compile_scene.h"
#include "render/compile/wide_blases.h"

namespace pt::cuda {

class CudaBackend final : public Backend, private SyncSteps {
public:
    CudaBackend();  // throws std::runtime_error when no CUDA device can be used
    ~CudaBackend() override;

    std::string name() const override { return "cuda"; }
    BackendCapabilities capabilities() const override { return {true, true, true}; }
    std::string deviceName() const override;
    SyncReport sync(const Scene& scene, const SceneDelta& changes, const ProgressFn& progress) override;
    void setToggles(const IntegratorToggles& toggles) override;
    void render(uint32_t passes) override;
    // Waits for the SAH trees building behind the first frame and swaps them in.
    std::optional<double> finishBackgroundWork() override;
    void resetAccumulation() override;
    uint32_t width() const override { return width_; }
    uint32_t height() const override { return height_; }
    void readBeauty(std::vector<float>& rgba) const override;
    bool copyBeautyToDevice(void* deviceRgba) const override;
    std::shared_ptr<void> allocateDeviceFrame() const override;
    std::optional<DeviceBvhFigures> measureDeviceBvh(const BvhBuildInput& input, uint32_t runs) override;
    KernelFigures kernelFigures() const override;
    std::vector<uint32_t> pathsAlivePerBounce() const override;
    BackendStats stats() const override;
    std::vector<ToggleState> toggleStates() const override;
    uint64_t deviceMemoryBytes() const override;  // the sum of deviceMemoryByBuffer()
    std::vector<std::pair<std::string, uint64_t>> deviceMemoryByBuffer() const override;
    std::vector<double> traceRays(const std::vector<Ray>& rays, bool anyHit, uint32_t runs,
                                  std::vector<Hit>* hits) override;
    int32_t sceneInstance(uint32_t hitInstance) const override {
        return compiled_ ? sceneInstanceOfHit(*compiled_, hitInstance) : -1;
    }
    void setAovs(AovMask aovs) override { aovsRequested_ = aovs; }
    void changeAovs(AovMask aovs) override;
    AovMask aovs() const override { return aovs_.mask; }
    uint32_t aovSamples(Aov aov) const override { return aovs_.samples(aov, stats_.samplesPerPixel); }
    void readAov(Aov aov, std::vector<float>& rgba) const override;
    // On the GPU (gpu_denoiser.h), from the sums in device memory.
    double readDenoised(std::vector<float>& rgba) const override;
    bool copyDenoisedToDevice(void* deviceRgba, double* seconds) const override;
    uint64_t aovBytes() const override;

    // Paths alive at the start of each bounce in the last wavefront wave (compaction's effect).
    const std::vector<uint32_t>& pathsPerBounce() const { return scheduler_.pathsPerBounce(); }
    // SAH cost of BLAS i now, and right after its last build (known once it has been refitted).
    float blasSahCost(uint32_t blas) const;
    float blasBuiltSahCost(uint32_t blas) const { return builtSah_[blas]; }
    static constexpr float kSahUnknown = -1.0f;

private:
    // The sync plan's steps (sync_steps.h), on the device: GPU refits (or LBVH rebuilds) of the
    // BLASes whose vertices moved, materials and instances uploaded in place, a GPU TLAS; the
    // host's TLAS only where the light table needs the scene's bounds.
    bool refitMeshes(const Scene& scene, const TouchedIds& meshes, SyncReport& report, SyncActions& actions,
                     bool* moved) override;
    bool updateMaterials(const Scene& scene, const TouchedIds& materials, SyncReport& report) override;
    bool updateInstances(const Scene& scene, SyncReport& report, SyncActions& actions,
                         bool* countChanged) override;
    bool lightsFollowMoves(bool instanceCountChanged) const override;
    void buildTlas(SyncReport& report) override;
    void updateLights(const Scene& scene, bool environment, SyncReport& report) override;
    void fullBuild(const Scene& scene, const ProgressFn& progress, SyncReport& report) override;
    // Uploads the vertices that changed, of the meshes the edit touched, and refits (or
    // rebuilds) the BLASes of meshes whose positions moved; returns Refit or Rebuild, or nothing
    // when no mesh moved. Sets needsFullBuild when a mesh changed size (a topology edit).
    std::optional<SyncAction> refitChangedMeshes(const Scene& scene, const TouchedIds& meshes,
                                                 SyncReport& report, bool& needsFullBuild);
    // Copies the vertices of triangle mesh `meshIndex` that differ from the host copy into it
    // and uploads them (the changed range of each array; all of them where the device's are
    // ahead of the host copy, skinned there); returns whether its positions changed.
    bool uploadChangedVertices(const Mesh& mesh, uint32_t meshIndex);
    // Refits BLAS i to its uploaded primitives, rebuilding it on the GPU when its SAH cost has
    // drifted past toggles_.rebuildSahRatio; returns whether it was rebuilt.
    bool refitBlas(uint32_t i, SyncReport& report);
    // Uploads the merged BLAS's vertices (merged_geometry.h, rewritten by compileInstances) and
    // refits it; returns Refit or Rebuild.
    SyncAction refitMergedBlas(SyncReport& report);
    void buildTlasOnDevice(SyncReport& report);
    // BLAS i's boxes made the exact bounds of its primitives' current boxes (primBoxes_).
    void refitToPrimitives(uint32_t i);
    // A GPU build of BLAS i over primBoxes_ (its primitives' boxes), in place of its tree: H-PLOC,
    // or an LBVH without IntegratorToggles::gpuPloc.
    void rebuildBlasOnDevice(uint32_t i);
    // The first frame's trees of the meshes the compile deferred (IntegratorToggles::
    // gpuFirstBuild): a GPU build each (rebuildBlasOnDevice), while their SAH trees build on the
    // host.
    void buildDeferredBlasesOnDevice(SyncReport& report);
    bool firstBuildOnGpu(std::string* why = nullptr) const;
    // Whether BLASes get compressed 8-wide nodes (gpuWideBvh, and a BVH at all).
    bool compressesBlases() const;
    // The compressed forms of the compiled BLASes (but the `deferred` ones', which come with
    // their SAH trees), collapsed on a thread behind the first frame, which walks the binary
    // nodes: on the H200 the collapse was 50-67 ms of a 64-instance field's first sync (one
    // 200k-triangle mesh). The thread reads compiled_'s BLASes: a sync that changes them lands
    // it first (waiting), and one that replaces them discards it.
    void startCompressing(const std::vector<uint32_t>& deferred);
    // Appends the forms once built (waiting for them where `wait`), for the BLASes whose trees
    // are still the compiled ones, requantised where refitted since. Returns whether the
    // collapse was done (landed, or refused).
    bool landCompressedBlases(bool wait);
    void discardCompressedBlases();
    // The background work that is done (all of it, waiting, where `wait`): compressed forms and
    // SAH trees.
    void landBackgroundWork(bool wait);
    // Swaps in the SAH trees that are built (all of them, waiting for them, where `wait`), with
    // their compressed forms under gpuWideBvh; a swap keeps the accumulation, as every BVH of
    // the same primitives gives the same hits. Returns whether anything landed.
    bool landSahTrees(bool wait);
    // BLAS `blas` was rebuilt, or every BLAS changed (a new compile): what is building for it
    // would be stale, and is dropped once done (never waited for).
    void retireSahTree(uint32_t blas);
    void retireSahTrees();
    void updateView();
    ScheduleOptions scheduleOptions() const;
    // The schedule and walk of the next pass: the toggles', or under the auto schedule the
    // chooser's (which times both walks where the scene has compressed nodes).
    PassSchedule nextPass() const;
    bool runsMegakernel() const { return nextPass().megakernel; }
    // Whether some BLAS has compressed nodes the kernels walk (gpuWideBvh; not those rebuilt
    // on the GPU, nor those first built there until their SAH trees land).
    bool hasCompressedNodes() const { return device_.anyCompressedForm(); }
    // The scene's features with the AOVs accumulated now: what picks the kernel variant.
    FeatureSet renderFeatures() const;
    // The AOVs the next wave records: those accumulated, less those the sample cap holds full.
    AovMask recordingAovs() const;
    uint64_t scheduleKey(uint32_t samplesPerWave) const;
    bool firstHitCacheApplies(std::string* why) const;

    cudaStream_t stream_ = nullptr;
    std::unique_ptr<CompiledScene> compiled_;
    // compiled_'s vertex arrays, pinned for vertex-edit uploads; declared after compiled_ so they
    // are unpinned before its memory goes.
    std::vector<PinnedRange> pinnedVertices_;
    // startCompressing's thread; declared after compiled_, which it reads, so that it is waited
    // for before compiled_ goes.
    std::future<CompressedBlases> compressing_;
    // Per BLAS: what to do with its compressed form when compressing_ lands.
    enum class CompressedPlan : uint8_t {
        Take,
        Requantize,  // refitted on the device since the compile
        Skip,        // built on the device since (a deferred mesh, a rebuild): another tree
    };
    std::vector<CompressedPlan> compressedPlan_;
    std::string compressedRefusal_;  // why the scene has no compressed nodes, where it was refused
    DeviceScene device_;
    LbvhBuilder lbvh_;  // BLAS builds without gpuPloc, and the TLAS beyond kHostTlasMaxInstances
    HplocBuilder hploc_;
    BvhLeafCollapse leafCollapse_;  // after either builder (IntegratorToggles::gpuLeafCollapse)
    PathScheduler scheduler_;
    ScheduleChooser scheduleChooser_;
    DeviceBuffer<double> sum_;
    AovMask aovsRequested_ = 0;             // as set, for the next reset
    AovSet aovs_;                           // as accumulated now
    DeviceBuffer<double> aovSums_;          // render/backend/aov.h's layout; none without AOVs
    mutable GpuDenoiser denoiser_;          // working memory only once a denoise ran
    mutable DeviceBuffer<float> denoised_;  // its RGBA output
    DeviceBuffer<Aabb> primBoxes_;
    DeviceBuffer<uint32_t> refitVisits_;
    DeviceBuffer<Ray> queryRays_;
    DeviceBuffer<Hit> queryHits_;
    DeviceBuffer<WorkClaims> queryClaims_;    // the ray-query kernel's (persistent_grid.cuh)
    std::vector<float> builtSah_;             // per BLAS, after its last build; kSahUnknown until needed
    std::vector<uint32_t> meshVertexOffset_;  // per mesh: its first vertex in compiled_->positions
    // The binned SAH trees building on the host behind the first frame, by BLAS, until their
    // compressed forms (where gpuWideBvh asks for them) have landed too.
    struct PendingSahTree {
        uint32_t blas;
        std::unique_ptr<BackgroundBvhBuild> build;
        // The BLAS was refitted since the build began (its positions moved): the tree is
        // refitted as it lands, and its compressed form requantised.
        bool refitted = false;
        bool treeLanded = false;  // its compressed form is still to come
    };
    std::vector<PendingSahTree> pendingSahTrees_;
    std::vector<std::unique_ptr<BackgroundBvhBuild>> staleSahTrees_;
    DeviceSkins skins_;
    // Per mesh: its vertices on the device were skinned there (device_skins.h), so compiled_'s
    // copy of them lags: the next host edit of the mesh uploads all of them.
    std::vector<bool> skinnedOnDevice_;
    // compiled_->tlasNodes (the host's TLAS, which the light table takes the scene's bounds
    // from) lags moved instances or refitted BLASes; rebuilt only when the lights need it.
    bool hostTlasStale_ = false;
    RenderScene view_{};
    IntegratorToggles toggles_;
    uint32_t width_ = 0, height_ = 0;
    BackendStats stats_;
};

}  // namespace pt::cuda
