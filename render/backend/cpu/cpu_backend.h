#pragma once
// CpuBackend: the shared per-ray code on all cores (TBB), progressive over 16x16 tiles.
// Accumulates in double so a million samples of a constant average to that constant.
#include <memory>

#include "render/backend/backend.h"
#include "render/backend/host_denoiser.h"
#include "render/backend/sync_steps.h"
#include "render/compile/compile_scene.h"
#include "render/integrator/path_state.h"

namespace pt {

class CpuBackend final : public Backend, private SyncSteps {
public:
    std::string name() const override { return "cpu"; }
    SyncReport sync(const Scene& scene, const SceneDelta& changes, const ProgressFn& progress) override;
    void setToggles(const IntegratorToggles& toggles) override;
    void render(uint32_t passes) override;
    void resetAccumulation() override;
    uint32_t width() const override { return width_; }
    uint32_t height() const override { return height_; }
    void readBeauty(std::vector<float>& rgba) const override;
    BackendStats stats() const override;
    std::vector<ToggleState> toggleStates() const override;
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
    uint64_t aovBytes() const override { return aovSums_.capacity() * sizeof(double); }
    double readDenoised(std::vector<float>& rgba) const override { return denoiser_.run(*this, rgba); }

private:
    // kPackets: each sample's camera rays of a 4 x 2 block of pixels go through one packet walk
    // (packet_traversal.h), the rest of each path as tracePath's; not with kAovs.
    // Whether render() traces camera rays in packets now; else `why` (where not null) says why.
    bool packetsApply(std::string* why) const;
    // `passes` samples of every pixel, all with the same AOVs recording; false where the
    // interrupt flag tore them (the accumulation is reset).
    bool renderSegment(uint32_t passes);
    template <bool kAovs, bool kPackets>
    bool renderTile(const RenderScene& scene, const AovBuffers& aovs, uint32_t y0, uint32_t y1, uint32_t x0,
                    uint32_t x1, uint32_t firstSample, uint32_t passes, PathCounters& counters);
    // The AOVs the next pass records: those accumulated, less those the sample cap holds full.
    AovMask recordingAovs() const { return aovs_.recording(aovSampleCap(), stats_.samplesPerPixel); }
    // The sync plan's steps (sync_steps.h), on the host: a host refit, materials and
    // instances compiled in place, the binned-SAH TLAS; the light table after every move (so an
    // edited scene renders bit for bit what a fresh compile of it renders).
    bool refitMeshes(const Scene& scene, const TouchedIds& meshes, SyncReport& report, SyncActions& actions,
                     bool* moved) override;
    bool updateMaterials(const Scene& scene, const TouchedIds& materials, SyncReport& report) override;
    bool updateInstances(const Scene& scene, SyncReport& report, SyncActions& actions,
                         bool* countChanged) override;
    bool lightsFollowMoves(bool) const override { return true; }
    void buildTlas(SyncReport& report) override;
    void updateLights(const Scene& scene, bool environment, SyncReport& report) override;
    void fullBuild(const Scene& scene, const ProgressFn& progress, SyncReport& report) override;
    // stats_.features: the compiled scene's, plus the AOVs applied now and the brute-force toggle.
    void updateStatsFeatures();
    // Refits BLAS `blas` on the host (host_refit.h); false where its SAH cost has drifted past
    // toggles_.rebuildSahRatio times its cost as built: the caller then compiles again.
    bool refitOnHost(uint32_t blas, SyncReport& report);
    // After a vertex edit: copies the moved meshes and refits their BLASes and the merged copies
    // of them (`refitted`: any moved). False where only a compile will do (a topology edit, or a
    // refit past the SAH drift ratio).
    bool refitMovedMeshes(const Scene& scene, const TouchedIds& meshes, SyncReport& report, bool& refitted);
    static constexpr float kSahUnknown = -1.0f;
    std::unique_ptr<CompiledScene> compiled_;
    RenderScene view_{};
    IntegratorToggles toggles_;
    uint32_t width_ = 0, height_ = 0;
    std::vector<double> sum_;      // RGB per pixel
    AovMask aovsRequested_ = 0;    // as set, for the next reset
    AovSet aovs_;                  // as accumulated now
    std::vector<double> aovSums_;  // render/backend/aov.h's layout; empty without AOVs
    BackendStats stats_;
    std::vector<float> builtSah_;    // per BLAS: its SAH cost as built, kSahUnknown until a refit
    mutable HostDenoiser denoiser_;  // its memory kept from one readDenoised to the next
};

}  // namespace pt
