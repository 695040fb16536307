#include "render/backend/cuda/cuda_backend.h"
#include "render/backend/cuda/display_copy.h"

#include <cstring>
#include <stdexcept>

#include "render/backend/cuda/cuda_device.h"
#include "render/backend/mean_image.h"
#include "render/backend/toggle_states.h"
#include "render/integrator/camera.h"
#include "render/util/stopwatch.h"

namespace pt::cuda {

namespace {

constexpr SceneChangeMask kNeedsFullBuild = SceneChanges::Topology | SceneChanges::Textures;

// Runs `step` and appends what it cost (device work included) to the report.
template <class Step>
double timedStep(cudaStream_t stream, SyncReport& report, const char* name, Step&& step) {
    const auto start = Clock::now();
    step();
    PT_CUDA_CHECK(cudaStreamSynchronize(stream));
    const double seconds = secondsSince(start);
    report.steps.push_back({name, seconds});
    return seconds;
}

bool sameBytes(const void* a, const void* b, size_t bytes) { return bytes == 0 || std::memcmp(a, b, bytes) == 0; }

bool emissionChanged(const std::vector<Material>& before, const std::vector<Material>& after) {
    if (before.size() != after.size()) return true;
    for (size_t i = 0; i < before.size(); ++i) {
        const Vec3 a = before[i].emittedRadiance(), b = after[i].emittedRadiance();
        if (!sameBytes(&a, &b, sizeof(Vec3)) || before[i].emissiveTexture.texture != after[i].emissiveTexture.texture) {
            return true;
        }
    }
    return false;
}

}  // namespace

CudaBackend::CudaBackend() {
    std::string why;
    if (!deviceAvailable(&why)) throw std::runtime_error("backend \"cuda\": " + why);
    PT_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));
}

CudaBackend::~CudaBackend() {
    if (stream_) cudaStreamDestroy(stream_);
}

SyncReport CudaBackend::sync(const Scene& scene, SceneChangeMask changes, const ProgressFn& progress) {
    const auto start = Clock::now();
    SyncReport report;
    const bool resized = scene.render.width != width_ || scene.render.height != height_;
    bool needsFullBuild = !compiled_ || (changes & kNeedsFullBuild);
    bool lightsDirty = (changes & (SceneChanges::Environment | SceneChanges::Lights)) != 0;
    bool tlasDirty = false;
    std::string action = changes == SceneChanges::Display ? "nothing" : "reset";
    // The report names the most expensive thing sync did; cheaper steps only replace "reset".
    const auto promote = [&action](const char* what) {
        if (action == "reset") action = what;
    };

    if (!needsFullBuild && (changes & SceneChanges::Geometry)) {
        if (const char* done = refitChangedMeshes(scene, report, needsFullBuild)) {
            tlasDirty = true;
            // The light table's weights follow emitter areas and the scene's bounds. Stale weights
            // would stay unbiased (NEE and MIS read the same table), but emissive triangles
            // deserve a table that matches their areas; other lights keep theirs.
            lightsDirty |= compiled_->emitters.triangles + compiled_->emitters.spheres > 0;
            action = done;
        }
    }
    if (!needsFullBuild && (changes & SceneChanges::Transforms)) {
        const size_t instancesBefore = compiled_->instances.size();
        timedStep(stream_, report, "instances", [&] {
            compileInstances(scene, *compiled_);
            device_.uploadInstances(*compiled_, stream_);
        });
        tlasDirty = true;
        // Emitters name instances by index: a changed instance list needs a new table, and so
        // do moved emissive surfaces (see above).
        lightsDirty |= compiled_->instances.size() != instancesBefore ||
                       compiled_->emitters.triangles + compiled_->emitters.spheres > 0;
        promote("TLAS");
    }
    if (!needsFullBuild && (changes & SceneChanges::Materials)) {
        timedStep(stream_, report, "materials", [&] {
            std::vector<Material> materials = compileMaterials(scene);
            lightsDirty |= emissionChanged(compiled_->materials, materials);
            compiled_->materials = std::move(materials);
            updateTransparency(*compiled_);
            device_.uploadMaterials(*compiled_, stream_);
        });
        promote("materials");
    }
    if (needsFullBuild) {
        fullBuild(scene, progress, report);
        action = "full build";
        lightsDirty = false;
        tlasDirty = false;
    }
    if (tlasDirty) buildTlasOnDevice(report);
    if (lightsDirty) {
        timedStep(stream_, report, "lights", [&] {
            // The light table weighs the environment by the scene's bounds: the host TLAS's root.
            if (tlasDirty) buildTlas(*compiled_);
            compileLights(scene, *compiled_);
            device_.uploadLights(*compiled_, stream_);
        });
        promote("lights");
    }
    report.action = action;
    compiled_->camera = makeRenderCamera(scene.camera, scene.render.width, scene.render.height);
    compiled_->settings = compileSettings(scene.render);
    width_ = scene.render.width;
    height_ = scene.render.height;
    updateView();
    if (resized) sum_.resize(size_t(width_) * height_ * 3);
    if (resized || changes != SceneChanges::Display) {
        scheduler_.invalidateFirstHits();
        resetAccumulation();
    }
    stats_.triangles = compiled_->stats.instancedTriangles;
    stats_.instances = compiled_->stats.instanceCount;
    for (const SyncStep& step : report.steps) {
        if (step.name.find("BLAS") != std::string::npos || step.name.find("TLAS") != std::string::npos) {
            report.bvhSeconds += step.seconds;
        }
    }
    report.seconds = secondsSince(start);
    return report;
}

void CudaBackend::fullBuild(const Scene& scene, const ProgressFn& progress, SyncReport& report) {
    CompileOptions options;
    options.bruteForce = toggles_.bruteForce;
    auto compiled = std::make_unique<CompiledScene>(compileRenderScene(scene, options, progress));
    report.steps.push_back({"compile scene (host)", compiled->stats.flattenSeconds + compiled->stats.lightSeconds});
    report.steps.push_back({"build BLAS (host, binned SAH)", compiled->stats.blasSeconds});
    pinnedVertices_.clear();
    compiled_ = std::move(compiled);
    pinnedVertices_.emplace_back(compiled_->positions.data(), compiled_->positions.size() * sizeof(Vec3));
    pinnedVertices_.emplace_back(compiled_->normals.data(), compiled_->normals.size() * sizeof(Vec3));
    pinnedVertices_.emplace_back(compiled_->tangents.data(), compiled_->tangents.size() * sizeof(Vec4));
    meshVertexOffset_.assign(scene.meshes.size(), 0);
    uint32_t vertices = 0;
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        meshVertexOffset_[i] = vertices;
        if (scene.meshes[i].kind == GeometryKind::Triangles) vertices += uint32_t(scene.meshes[i].positions.size());
    }
    timedStep(stream_, report, "upload", [&] { device_.uploadAll(*compiled_, stream_); });
    // Measured when a BLAS is first refitted, not here: most meshes never are.
    builtSah_.assign(device_.blasCount(), kSahUnknown);
    buildTlasOnDevice(report);
}

const char* CudaBackend::refitChangedMeshes(const Scene& scene, SyncReport& report, bool& needsFullBuild) {
    if (scene.meshes.size() != device_.blasCount()) {
        needsFullBuild = true;
        return nullptr;
    }
    std::vector<uint32_t> changed;
    timedStep(stream_, report, "upload vertices", [&] {
        for (uint32_t i = 0; i < device_.blasCount(); ++i) {
            const Mesh& mesh = scene.meshes[i];
            const BlasRef& blas = device_.blas(i);
            if (mesh.primitiveCount() != blas.primitiveCount) {
                needsFullBuild = true;
                return;
            }
            if (mesh.kind == GeometryKind::Spheres) {
                Vec4* stored = compiled_->spheres.data() + blas.primitiveOffset;
                if (sameBytes(stored, mesh.spheres.data(), mesh.spheres.size() * sizeof(Vec4))) continue;
                std::memcpy(stored, mesh.spheres.data(), mesh.spheres.size() * sizeof(Vec4));
                device_.uploadSpheres(*compiled_, i, stream_);
            } else {
                const uint32_t first = meshVertexOffset_[i], count = uint32_t(mesh.positions.size());
                if (first + count > compiled_->positions.size()) {
                    needsFullBuild = true;
                    return;
                }
                Vec3* stored = compiled_->positions.data() + first;
                if (sameBytes(stored, mesh.positions.data(), count * sizeof(Vec3))) continue;
                std::memcpy(stored, mesh.positions.data(), count * sizeof(Vec3));
                if (mesh.normals.size() == count) {
                    std::memcpy(compiled_->normals.data() + first, mesh.normals.data(), count * sizeof(Vec3));
                }
                if (!compiled_->tangents.empty() && mesh.tangents.size() == count) {
                    std::memcpy(compiled_->tangents.data() + first, mesh.tangents.data(), count * sizeof(Vec4));
                }
                device_.uploadVertices(*compiled_, first, count, stream_);
            }
            changed.push_back(i);
        }
    });
    if (needsFullBuild || changed.empty()) return nullptr;

    const RenderScene deviceView = device_.view(*compiled_);
    bool rebuilt = false;
    for (uint32_t i : changed) {
        const BlasRef& blas = device_.blas(i);
        if (builtSah_[i] == kSahUnknown) builtSah_[i] = blasSahCost(i);  // still as built
        primBoxes_.resize(blas.primitiveCount);
        refitVisits_.resize(device_.blasNodeCapacity(i));
        timedStep(stream_, report, "refit BLAS", [&] {
            computePrimitiveBoxes(deviceView, blas, primBoxes_.data(), stream_);
            refitBvh(device_.blasNodes(i), blas.nodeCount, device_.blasParents(i), device_.blasPrimIndices(i),
                     primBoxes_.data(), refitVisits_.data(), stream_);
        });
        const float cost = blasSahCost(i);
        if (cost > toggles_.rebuildSahRatio * builtSah_[i]) {
            timedStep(stream_, report, "rebuild BLAS (GPU LBVH)", [&] {
                const uint32_t nodes = lbvhNodeCount(blas.primitiveCount);
                lbvh_.build(primBoxes_.data(), blas.primitiveCount, device_.blasNodes(i), device_.blasPrimIndices(i),
                            stream_);
                device_.setBlasNodeCount(i, nodes, stream_);
                computeParents(device_.blasNodes(i), nodes, device_.blasParents(i), stream_);
            });
            builtSah_[i] = blasSahCost(i);
            rebuilt = true;
        }
    }
    return rebuilt ? "rebuild" : "refit";
}

void CudaBackend::buildTlasOnDevice(SyncReport& report) {
    const uint32_t count = device_.instanceCount();
    timedStep(stream_, report, "build TLAS (GPU LBVH)", [&] {
        device_.tlasNodes.resize(lbvhNodeCount(count));
        device_.tlasInstanceIndices.resize(count);
        primBoxes_.resize(count);
        computeInstanceBoxes(device_.instances(), count, device_.deviceBlases(), device_.allBlasNodes(),
                             primBoxes_.data(), stream_);
        lbvh_.build(primBoxes_.data(), count, device_.tlasNodes.data(), device_.tlasInstanceIndices.data(), stream_);
    });
}

float CudaBackend::blasSahCost(uint32_t blas) const {
    return sahCostOnDevice(device_.blasNodes(blas), device_.blas(blas).nodeCount, stream_);
}

void CudaBackend::updateView() {
    view_ = device_.view(*compiled_);  // bruteForce comes from the compile options
    applyIntegratorToggles(toggles_, view_.settings);
}

void CudaBackend::setToggles(const IntegratorToggles& toggles) {
    const bool bvhChanged = toggles.bruteForce != toggles_.bruteForce;
    toggles_ = toggles;
    if (bvhChanged) {  // the next sync recompiles (and checks the budget)
        pinnedVertices_.clear();
        compiled_.reset();
    }
    if (compiled_) {
        updateView();
        scheduler_.invalidateFirstHits();
        resetAccumulation();
    }
}

bool CudaBackend::firstHitCacheApplies(std::string* why) const {
    const char* reason = nullptr;
    if (toggles_.megakernel) reason = "the megakernel traces every ray itself";
    else if (toggles_.pixelJitter) reason = "pixel jitter is on, so camera rays differ per sample";
    else if (compiled_ && compiled_->camera.lensRadius > 0.0f) reason = "the thin lens moves camera rays per sample";
    if (reason && why) *why = reason;
    return reason == nullptr;
}

ScheduleOptions CudaBackend::scheduleOptions() const {
    ScheduleOptions o;
    o.megakernel = toggles_.megakernel;
    o.compaction = toggles_.streamCompaction;
    o.materialSort = toggles_.materialSort;
    o.firstHitCache = toggles_.firstHitCache && firstHitCacheApplies(nullptr);
    o.materialCount = compiled_ ? uint32_t(compiled_->materials.size()) : 1u;
    return o;
}

void CudaBackend::resetAccumulation() {
    sum_.resize(size_t(width_) * height_ * 3);
    sum_.fillZero(stream_);
    aovs_ = aovsRequested_;
    const size_t aovDoubles = aovDoublesPerPixel(aovs_) * width_ * height_;
    // A fresh buffer when the size changes, so device memory follows the AOVs enabled now.
    if (aovSums_.size() != aovDoubles) aovSums_ = DeviceBuffer<double>(aovDoubles);
    aovSums_.fillZero(stream_);
    scheduler_.resetCounters(stream_);
    PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
    stats_.samplesPerPixel = 0;
    stats_.renderSeconds = 0.0;
    stats_.rays = 0;
    stats_.nonfiniteSamples = 0;
}

void CudaBackend::render(uint32_t passes) {
    if (!compiled_ || passes == 0) return;
    const auto start = Clock::now();
    const AovBuffers aovs = aovBuffersIn(aovSums_.data(), aovs_, size_t(width_) * height_);
    scheduler_.render(view_, stats_.samplesPerPixel, passes, scheduleOptions(), sum_.data(), aovs, stream_);
    PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
    stats_.samplesPerPixel += passes;
    stats_.renderSeconds += secondsSince(start);
}

void CudaBackend::readBeauty(std::vector<float>& rgba) const {
    const std::vector<double> sum = sum_.download();
    meanImageFromSums(sum.data(), size_t(width_) * height_, stats_.samplesPerPixel, rgba);
}

std::vector<uint32_t> CudaBackend::pathsAlivePerBounce() const {
    return toggles_.megakernel ? std::vector<uint32_t>{} : scheduler_.pathsPerBounce();
}

bool CudaBackend::copyBeautyToDevice(void* deviceRgba) const {
    launchMeanToRgba(sum_.data(), size_t(width_) * height_, stats_.samplesPerPixel, static_cast<float*>(deviceRgba),
                     stream_);
    PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
    return true;
}

void CudaBackend::readAov(Aov aov, std::vector<float>& rgba) const {
    requireAov(aovs_, aov);
    const size_t pixels = size_t(width_) * height_;
    std::vector<double> plane(pixels * aovChannels(aov));
    aovSums_.downloadAt(aovPlaneOffset(aovs_, aov, pixels), plane.data(), plane.size());
    aovImageFromSums(aov, plane.empty() ? nullptr : plane.data(), pixels, stats_.samplesPerPixel, rgba);
}

uint64_t CudaBackend::aovBytes() const { return aovSums_.bytes() + scheduler_.aovBytes(); }

BackendStats CudaBackend::stats() const {
    BackendStats s = stats_;
    const RenderCounters counters = scheduler_.counters();
    s.rays = counters.rays;
    s.nonfiniteSamples = counters.nonfinite;
    return s;
}

std::vector<ToggleState> CudaBackend::toggleStates() const {
    std::vector<ToggleState> states = integratorToggleStates(toggles_);
    for (ToggleState& s : states) {
        if (!s.requested) continue;
        if (s.name == "first_hit_cache") {
            s.active = firstHitCacheApplies(&s.note);
        } else if ((s.name == "compaction" || s.name == "material_sort") && toggles_.megakernel) {
            s.active = false;
            s.note = "wavefront only; the megakernel is on";
        }
    }
    return states;
}

std::vector<double> CudaBackend::traceRays(const std::vector<Ray>& rays, bool anyHit, uint32_t runs,
                                           std::vector<Hit>* hits) {
    std::vector<double> seconds;
    if (!compiled_) return seconds;
    queryRays_.upload(rays, stream_);
    queryHits_.resize(rays.size());
    cudaEvent_t begin = nullptr, end = nullptr;
    PT_CUDA_CHECK(cudaEventCreate(&begin));
    PT_CUDA_CHECK(cudaEventCreate(&end));
    try {
        for (uint32_t run = 0; run < runs; ++run) {
            PT_CUDA_CHECK(cudaEventRecord(begin, stream_));
            launchTraceRays(view_, queryRays_.data(), uint32_t(rays.size()), anyHit, queryHits_.data(), stream_);
            PT_CUDA_CHECK(cudaEventRecord(end, stream_));
            PT_CUDA_CHECK(cudaEventSynchronize(end));
            float ms = 0.0f;
            PT_CUDA_CHECK(cudaEventElapsedTime(&ms, begin, end));
            seconds.push_back(double(ms) * 1e-3);
        }
    } catch (...) {
        cudaEventDestroy(begin);
        cudaEventDestroy(end);
        throw;
    }
    cudaEventDestroy(begin);
    cudaEventDestroy(end);
    if (hits) queryHits_.download(*hits);
    return seconds;
}

uint64_t CudaBackend::deviceMemoryBytes() const {
    return device_.bytes() + scheduler_.bytes() + sum_.bytes() + aovSums_.bytes() + primBoxes_.bytes() +
           refitVisits_.bytes();
}

}  // namespace pt::cuda
