#include "render/backend/cpu/cpu_backend.h"

#include <tbb/blocked_range.h>
#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>

#include "render/backend/mean_image.h"
#include "render/backend/sync_steps.h"
#include "render/backend/toggle_states.h"
#include "render/bvh/packet_traversal.h"
#include "render/bvh/wide_walk_simd.h"
#include "render/compile/host_refit.h"
#include "render/compile/scene_features.h"
#include "render/compile/wide_blases.h"
#include "render/integrator/camera.h"
#include "render/integrator/path_tracer.h"
#include "render/util/stopwatch.h"

namespace pt {

SyncReport CpuBackend::sync(const Scene& scene, const SceneDelta& changes, const ProgressFn& progress) {
    const auto start = Clock::now();
    SyncReport report;
    const bool resized = scene.render.width != width_ || scene.render.height != height_;
    const SyncPlan plan = planSync(compiled_.get(), scene, changes);
    report.action = syncActionName(executeSyncPlan(plan, scene, *this, report, progress));
    compiled_->camera = makeRenderCamera(scene.camera, scene.render.width, scene.render.height);
    compiled_->settings = compileSettings(scene.render);
    // Edits patch the compiled scene; what it uses now is what the kernels must cover.
    updateFeatures(scene, *compiled_);
    view_ = compiled_->view();
    applyIntegratorToggles(toggles_, view_.settings);
    width_ = scene.render.width;
    height_ = scene.render.height;
    if (resized || plan.reset) resetAccumulation();
    updateStatsFeatures();
    stats_.triangles = compiled_->stats.instancedTriangles;
    stats_.instances = compiled_->stats.instanceCount;
    report.seconds = secondsSince(start);
    return report;
}

bool CpuBackend::refitMeshes(const Scene& scene, const TouchedIds& meshes, SyncReport& report,
                             SyncActions& actions, bool* moved) {
    if (compiled_->bruteForce) return false;  // brute force (validation only) keeps no BVH to refit
    if (!refitMovedMeshes(scene, meshes, report, *moved)) return false;
    if (*moved) actions.add(SyncAction::Refit);
    return true;
}

bool CpuBackend::updateMaterials(const Scene& scene, const TouchedIds& materials, SyncReport& report) {
    bool emissionChanged = false;
    timedHostStep(report, "materials", [&] {
        emissionChanged = updateEditedMaterials(scene, *compiled_, materials).emissionChanged;
    });
    return emissionChanged;
}

bool CpuBackend::updateInstances(const Scene& scene, SyncReport& report, SyncActions& actions,
                                 bool* countChanged) {
    if (compiled_->bruteForce) return false;
    const size_t before = compiled_->instances.size();
    // A merged instance that moved moves its copy in the merged BLAS, which is refitted.
    bool mergedMoved = false;
    timedHostStep(report, "instances", [&] { mergedMoved = compileInstances(scene, *compiled_); });
    *countChanged = compiled_->instances.size() != before;
    if (!mergedMoved) return true;
    actions.add(SyncAction::Refit);
    return refitOnHost(compiled_->merged.blas, report);
}

void CpuBackend::buildTlas(SyncReport& report) {
    report.bvhSeconds += timedHostStep(report, "TLAS", [&] { pt::buildTlas(*compiled_); });
}

void CpuBackend::updateLights(const Scene& scene, bool environment, SyncReport& report) {
    // The environment's sampling tables change only with the environment.
    timedHostStep(report, "lights", [&] {
        compileLights(scene, *compiled_, environment ? LightsUpdate::All : LightsUpdate::KeepEnvironment);
    });
}

void CpuBackend::fullBuild(const Scene& scene, const ProgressFn& progress, SyncReport& report) {
    CompileOptions options;
    options.bruteForce = toggles_.bruteForce;
    options.mergeSmallInstances = toggles_.mergeInstances;
    options.wideBvh = toggles_.wideBvh;
    compiled_ = std::make_unique<CompiledScene>(compileRenderScene(scene, options, progress));
    builtSah_.assign(compiled_->blases.size(), kSahUnknown);  // measured at a first refit
    report.bvhSeconds = compiled_->stats.blasSeconds + compiled_->stats.tlasSeconds;
}

bool CpuBackend::refitMovedMeshes(const Scene& scene, const TouchedIds& meshes, SyncReport& report,
                                  bool& refitted) {
    std::optional<std::vector<uint32_t>> moved;
    timedHostStep(report, "copy vertices", [&] { moved = copyMovedMeshes(scene, meshes, *compiled_); });
    if (!moved) return false;  // meshes changed size: a topology edit
    bool mergedMoved = false;
    for (const uint32_t mesh : *moved) {
        if (!refitOnHost(mesh, report)) return false;
        for (const MergedPiece& piece : compiled_->merged.pieces) mergedMoved |= piece.mesh == mesh;
    }
    // The merged BLAS holds world-space copies of its pieces' meshes: they follow.
    if (mergedMoved && bakeMergedGeometry(scene, *compiled_) && !refitOnHost(compiled_->merged.blas, report))
        return false;
    refitted = !moved->empty();
    return true;
}

bool CpuBackend::refitOnHost(uint32_t blas, SyncReport& report) {
    if (builtSah_[blas] == kSahUnknown) builtSah_[blas] = blasSahCost(*compiled_, blas);  // still as built
    report.bvhSeconds += timedHostStep(report, "refit BLAS", [&] {
        refitBlasOnHost(*compiled_, blas);
        refreshWideBlas(*compiled_, blas);
    });
    return !(blasSahCost(*compiled_, blas) > toggles_.rebuildSahRatio * builtSah_[blas]);
}

void CpuBackend::setToggles(const IntegratorToggles& toggles) {
    const bool bvhChanged = toggles.bruteForce != toggles_.bruteForce ||
                            toggles.mergeInstances != toggles_.mergeInstances ||
                            toggles.wideBvh != toggles_.wideBvh;
    toggles_ = toggles;
    if (bvhChanged) compiled_.reset();  // the next sync recompiles (and checks the budget)
    if (compiled_) {
        applyIntegratorToggles(toggles_, view_.settings);
        resetAccumulation();
    }
}

bool CpuBackend::packetsApply(std::string* why) const {
    const auto refuse = [&](const char* reason) {
        if (why) *why = reason;
        return false;
    };
    if (!toggles_.rayPackets) return refuse("");
    if ((recordingAovs() & kPathAovs) != 0) return refuse("path AOVs record each camera ray's traversal");
    if (compiled_ && !packetWalkApplies(view_)) {
        return refuse(wideWalkSimdLevel() != SimdLevel::Avx2 ? "the processor runs no AVX2"
                                                             : "needs the 8-wide BVH and no brute force");
    }
    return true;
}

std::vector<ToggleState> CpuBackend::toggleStates() const {
    std::vector<ToggleState> states = integratorToggleStates(toggles_);
    for (ToggleState& s : states) {
        if (toggleRow(s.id).scope == ToggleScope::GpuScheduling) {
            s.active = false;
            s.note = "CUDA only: the CPU backend runs one path per thread";
        } else if (s.id == ToggleId::RayPackets && s.requested) {
            s.active = packetsApply(&s.note);
        }
    }
    return states;
}

void CpuBackend::resetAccumulation() {
    sum_.assign(size_t(width_) * height_ * 3, 0.0);
    aovs_ = AovSet{aovsRequested_, {}};
    const size_t aovDoubles = aovDoublesPerPixel(aovs_.mask) * width_ * height_;
    // A fresh vector when the size changes, so memory follows the AOVs enabled now.
    if (aovSums_.size() != aovDoubles) {
        aovSums_ = std::vector<double>(aovDoubles, 0.0);
    } else {
        std::fill(aovSums_.begin(), aovSums_.end(), 0.0);
    }
    updateStatsFeatures();  // the AOVs just applied
    stats_.samplesPerPixel = 0;
    stats_.renderSeconds = 0.0;
    stats_.rays = 0;
    stats_.nonfiniteSamples = 0;
}

void CpuBackend::updateStatsFeatures() {
    stats_.features = compiled_ ? compiled_->features : 0u;
    if (aovs_.mask != 0) stats_.features |= feature::kAovs;
    if (toggles_.bruteForce) stats_.features |= feature::kBruteForce;
}

// In segments that end where a capped AOV fills up, so that it stops exactly at its cap.
void CpuBackend::render(uint32_t passes) {
    if (!compiled_) return;
    while (passes > 0) {
        const uint32_t n = std::min(passes, aovs_.samplesUntilFull(aovSampleCap(), stats_.samplesPerPixel));
        if (!renderSegment(n)) return;
        passes -= n;
    }
}

bool CpuBackend::renderSegment(uint32_t passes) {
    const auto start = Clock::now();
    const uint32_t firstSample = stats_.samplesPerPixel;
    const RenderScene& scene = view_;
    tbb::combinable<PathCounters> counters;
    constexpr size_t kTile = 16;
    const AovMask recording = recordingAovs();
    const AovBuffers aovs = aovBuffersIn(aovSums_.data(), aovs_, size_t(width_) * height_, recording);
    const bool pathAovs = (recording & kPathAovs) != 0;
    const bool packets = packetsApply(nullptr);
    std::atomic<bool> torn{false};
    tbb::parallel_for(
        tbb::blocked_range2d<uint32_t>(0, height_, kTile, 0, width_, kTile),
        [&](const tbb::blocked_range2d<uint32_t>& tile) {
            const auto rows = tile.rows(), cols = tile.cols();
            const uint32_t y0 = rows.begin(), y1 = rows.end(), x0 = cols.begin(), x1 = cols.end();
            PathCounters& c = counters.local();
            const bool done =
                pathAovs  ? renderTile<true, false>(scene, aovs, y0, y1, x0, x1, firstSample, passes, c)
                : packets ? renderTile<false, true>(scene, aovs, y0, y1, x0, x1, firstSample, passes, c)
                          : renderTile<false, false>(scene, aovs, y0, y1, x0, x1, firstSample, passes, c);
            if (!done) torn = true;
        });
    if (torn) {
        resetAccumulation();
        return false;
    }
    counters.combine_each([&](const PathCounters& c) {
        stats_.rays += c.rays;
        stats_.nonfiniteSamples += c.nonfiniteSamples;
    });
    aovs_.skip(recording, passes);
    stats_.samplesPerPixel += passes;
    stats_.renderSeconds += secondsSince(start);
    return true;
}

// Each pixel's samples in order, by one thread: the sums (and Welford's variance) need no atomics.
// kAovs: the path records AOVs (kPathAovs); without, tracePath has no AOV code. kPackets: the
// tile's pixels go in blocks of 4 x 2, each sample's eight camera rays through one packet walk
// (more coherent than a row of eight: on a 1M-triangle sphere 8-10% more camera rays a second),
// each pixel still taking its samples in order. Returns false where the interrupt flag stopped
// it (checked before every sample: a call may ask for many samples a pixel, and one relaxed
// load is nothing beside a path).
template <bool kAovs, bool kPackets>
bool CpuBackend::renderTile(const RenderScene& scene, const AovBuffers& aovs, uint32_t y0, uint32_t y1,
                            uint32_t x0, uint32_t x1, uint32_t firstSample, uint32_t passes,
                            PathCounters& counters) {
    static_assert(!(kAovs && kPackets), "packets trace paths without AOVs");
    constexpr uint32_t kBlockWidth = kPackets ? 4 : 1, kBlockHeight = kPackets ? 2 : 1;
    constexpr uint32_t kBlock = kBlockWidth * kBlockHeight;
    static_assert(kBlock <= kRayPacketSize, "a block's camera rays fill one packet");
    const bool variance = aovs.has(Aov::Variance);
    for (uint32_t by = y0; by < y1; by += kBlockHeight) {
        for (uint32_t bx = x0; bx < x1; bx += kBlockWidth) {
            // The block's pixels inside the tile, row by row.
            uint32_t px[kBlock] = {}, py[kBlock] = {}, n = 0;
            for (uint32_t y = by; y < std::min(by + kBlockHeight, y1); ++y) {
                for (uint32_t x = bx; x < std::min(bx + kBlockWidth, x1); ++x) px[n] = x, py[n++] = y;
            }
            for (uint32_t s = 0; s < passes; ++s) {
                if (interruptRequested()) return false;
                const uint32_t sample = firstSample + s;
                Vec3 L[kBlock];
                AovSample aov;
                if constexpr (kPackets) {
                    PathState states[kBlock];
                    Ray rays[kBlock];
                    Hit hits[kBlock];
                    for (uint32_t k = 0; k < n; ++k) {
                        states[k] = generatePath(scene, px[k], py[k], sample);
                        rays[k] = states[k].ray;
                    }
                    intersectClosestGrouped(scene, rays, n, hits);  // a wide lens's blocks one by one
                    for (uint32_t k = 0; k < n; ++k)
                        L[k] = finishPathFromCameraHit(scene, states[k], hits[k], counters);
                } else {
                    L[0] = tracePath<kAovs>(scene, px[0], py[0], sample, counters, &aov);
                }
                for (uint32_t k = 0; k < n; ++k) {
                    const uint32_t pixel = py[k] * width_ + px[k];
                    double* sum = &sum_[size_t(pixel) * 3];
                    sum[0] += L[k].x;
                    sum[1] += L[k].y;
                    sum[2] += L[k].z;
                    if (kAovs) {
                        addAovSample(aovs, pixel, sample, aov);
                        addAovCost(aovs, pixel, aov.cost);
                    }
                    if (variance) addVarianceSample(aovs, pixel, sample, L[k]);
                }
            }
        }
    }
    return true;
}

void CpuBackend::readBeauty(std::vector<float>& rgba) const {
    meanImageFromSums(sum_.data(), size_t(width_) * height_, stats_.samplesPerPixel, rgba);
}

void CpuBackend::readAov(Aov aov, std::vector<float>& rgba) const {
    requireAov(aovs_.mask, aov);
    const size_t pixels = size_t(width_) * height_;
    const double* plane =
        aovChannels(aov) ? aovSums_.data() + aovPlaneOffset(aovs_.mask, aov, pixels) : nullptr;
    aovImageFromSums(aov, plane, pixels, aovSamples(aov), stats_.samplesPerPixel, rgba);
}

void CpuBackend::changeAovs(AovMask aovs) {
    aovsRequested_ = aovs;
    if (aovs == aovs_.mask) return;
    const size_t pixels = size_t(width_) * height_;
    std::vector<double> sums(aovDoublesPerPixel(aovs) * pixels, 0.0);
    for (const AovPlaneMove& m : keptAovPlanes(aovs_.mask, aovs, pixels))
        std::copy_n(aovSums_.begin() + ptrdiff_t(m.from), m.doubles, sums.begin() + ptrdiff_t(m.to));
    aovSums_ = std::move(sums);
    aovs_ = aovs_.changedTo(aovs, stats_.samplesPerPixel);
    updateStatsFeatures();
}

BackendStats CpuBackend::stats() const { return stats_; }

namespace {

// Rays [begin, end) of `rays` into `results` (closest hits, or any hits as traceRays reports
// them: instance 0 where occluded), in packets of eight where `packets`: closest hits only
// where the eight point about one way (raysCoherent); shadow rays whichever way they point
// (bench's 1M sphere, toward two lights: 2.5% faster so, and 2-8% slower split by raysCoherent).
void traceRange(const RenderScene& scene, const std::vector<Ray>& rays, size_t begin, size_t end, bool anyHit,
                bool packets, std::vector<Hit>& results) {
    const auto occlusion = [](bool occluded) {
        Hit hit{};
        hit.instance = occluded ? 0u : Hit::kNoHit;
        return hit;
    };
    const size_t packetSize = packets ? kRayPacketSize : 1;
    for (size_t i = begin; i < end; i += packetSize) {
        const uint32_t n = uint32_t(std::min(packetSize, end - i));
        if (n > 1 && anyHit) {
            const uint32_t occluded = intersectAnyPacket(scene, &rays[i], n);
            for (uint32_t k = 0; k < n; ++k) results[i + k] = occlusion((occluded >> k) & 1u);
        } else if (n > 1) {
            intersectClosestGrouped(scene, &rays[i], n, &results[i]);
        } else if (anyHit) {
            results[i] = occlusion(intersectAny(scene, rays[i]));
        } else {
            intersectClosest(scene, rays[i], results[i]);
        }
    }
}

}  // namespace

std::vector<double> CpuBackend::traceRays(const std::vector<Ray>& rays, bool anyHit, uint32_t runs,
                                          std::vector<Hit>* hits) {
    std::vector<double> seconds;
    if (!compiled_) return seconds;
    std::vector<Hit> results(rays.size());
    // Packets of eight consecutive rays (neighbouring pixels' rays in bench's sets) where the
    // toggle and the scene allow.
    const bool packets = toggles_.rayPackets && packetWalkApplies(view_);
    for (uint32_t run = 0; run < runs; ++run) {
        const auto start = Clock::now();
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024),
                          [&](const tbb::blocked_range<size_t>& r) {
                              traceRange(view_, rays, r.begin(), r.end(), anyHit, packets, results);
                          });
        seconds.push_back(secondsSince(start));
    }
    if (hits) *hits = std::move(results);
    return seconds;
}

}  // namespace pt
