#include "render/backend/cuda/cuda_backend.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <future>
#include <new>
#include <stdexcept>
#include <utility>

#include "render/backend/cuda/cuda_device.h"
#include "render/backend/cuda/device_bvh_figures.h"
#include "render/backend/cuda/display_copy.h"
#include "render/backend/cuda/stream_timer.h"
#include "render/backend/mean_image.h"
#include "render/backend/toggle_states.h"
#include "render/compile/compile_geometry.h"
#include "render/integrator/camera.h"
#include "render/scene/scene_animation.h"
#include "render/util/large_array.h"
#include "render/util/stopwatch.h"

namespace pt::cuda {

namespace {

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

bool sameBytes(const void* a, const void* b, size_t bytes) {
    return bytes == 0 || std::memcmp(a, b, bytes) == 0;
}

// Where `incoming` differs from `stored` (count elements each): copies that range into
// `stored` and returns it as {first, count}, count 0 when nothing differs. Compared in blocks
// from both ends, so an edit of a few vertices copies and uploads only their block range, and
// an edit of every vertex reads each array once.
template <class T>
std::pair<uint32_t, uint32_t> copyChangedRange(T* stored, const T* incoming, uint32_t count) {
    constexpr uint32_t kBlock = 4096;  // elements per comparison
    uint32_t first = 0;
    while (first < count) {
        const uint32_t n = std::min(kBlock, count - first);
        if (!sameBytes(stored + first, incoming + first, n * sizeof(T))) break;
        first += n;
    }
    if (first == count) return {count, 0u};
    uint32_t end = count;
    while (end - first > kBlock) {
        const uint32_t n = std::min(kBlock, end - first);
        if (!sameBytes(stored + end - n, incoming + end - n, n * sizeof(T))) break;
        end -= n;
    }
    std::memcpy(stored + first, incoming + first, size_t(end - first) * sizeof(T));
    return {first, end - first};
}

// Meshes of at least this many primitives get their first frame's tree from the GPU
// (IntegratorToggles::gpuFirstBuild). Below it the host's build is quick anyway: 262,144
// triangles are about 40 ms of binned SAH on the H200 host's 16 cores (6.6 Mtris/s at 10M).
constexpr uint32_t kGpuFirstBuildMinPrimitives = 1u << 18;

}  // namespace

CudaBackend::CudaBackend() {
    std::string why;
    if (!deviceAvailable(&why)) throw std::runtime_error("backend \"cuda\": " + why);
    PT_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));
}

CudaBackend::~CudaBackend() {
    if (stream_) cudaStreamDestroy(stream_);
}

SyncReport CudaBackend::sync(const Scene& scene, const SceneDelta& changes, const ProgressFn& progress) {
    const auto start = Clock::now();
    SyncReport report;
    const bool resized = scene.render.width != width_ || scene.render.height != height_;
    const SyncPlan plan = planSync(compiled_.get(), scene, changes);
    // The collapse behind the first frame reads the compiled BLASes, which these change.
    if (plan.fullBuild)
        discardCompressedBlases();
    else if (plan.refitGeometry || plan.instances)
        landCompressedBlases(true);
    report.action = syncActionName(executeSyncPlan(plan, scene, *this, report, progress));
    compiled_->camera = makeRenderCamera(scene.camera, scene.render.width, scene.render.height);
    compiled_->settings = compileSettings(scene.render);
    width_ = scene.render.width;
    height_ = scene.render.height;
    // Edits patch the compiled scene; what it uses now decides the next render's kernel variant.
    updateFeatures(scene, *compiled_);
    updateView();
    if (resized) sum_.resize(size_t(width_) * height_ * 3);
    if (resized || plan.reset) {
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

bool CudaBackend::refitMeshes(const Scene& scene, const TouchedIds& meshes, SyncReport& report,
                              SyncActions& actions, bool* moved) {
    bool needsFullBuild = false;
    const std::optional<SyncAction> done = refitChangedMeshes(scene, meshes, report, needsFullBuild);
    if (done) {
        actions.add(*done);
        hostTlasStale_ = true;
    }
    *moved = done.has_value();
    return !needsFullBuild;
}

bool CudaBackend::updateMaterials(const Scene& scene, const TouchedIds& materials, SyncReport& report) {
    bool emissionChanged = false;
    timedStep(stream_, report, "materials", [&] {
        const MaterialsUpdate update = updateEditedMaterials(scene, *compiled_, materials);
        emissionChanged = update.emissionChanged;
        if (update.all) {
            device_.uploadMaterials(*compiled_, stream_);
        } else {
            for (const uint32_t m : update.copied) device_.uploadMaterial(*compiled_, m, stream_);
        }
    });
    return emissionChanged;
}

bool CudaBackend::updateInstances(const Scene& scene, SyncReport& report, SyncActions& actions,
                                  bool* countChanged) {
    const size_t before = compiled_->instances.size();
    // O(instances x slots): transforms, materials of each slot, statistics.
    bool mergedMoved = false;
    timedStep(stream_, report, "instances", [&] {
        mergedMoved = compileInstances(scene, *compiled_);
        device_.uploadInstances(*compiled_, stream_);
    });
    if (mergedMoved) actions.add(refitMergedBlas(report));
    hostTlasStale_ = true;
    *countChanged = compiled_->instances.size() != before;
    return true;
}

bool CudaBackend::lightsFollowMoves(bool instanceCountChanged) const {
    // Emitters name instances by index: a changed instance list needs a new table. Moved
    // emissive surfaces deserve one that matches their areas; other lights keep their weights,
    // stale but unbiased (NEE and MIS read the same table), which spares a drag the host TLAS
    // the scene bounds come from.
    return instanceCountChanged || compiled_->emitters.triangles + compiled_->emitters.spheres > 0;
}

void CudaBackend::buildTlas(SyncReport& report) { buildTlasOnDevice(report); }

void CudaBackend::updateLights(const Scene& scene, bool environment, SyncReport& report) {
    if (hostTlasStale_) {
        // The light table weighs the environment and directional lights by the scene's
        // bounds, the host TLAS's root: O(instances log instances) from the BLAS roots.
        timedStep(stream_, report, "TLAS (host, scene bounds)", [&] { pt::buildTlas(*compiled_); });
        hostTlasStale_ = false;
    }
    // The environment's sampling tables change only with the environment.
    timedStep(stream_, report, "lights", [&] {
        compileLights(scene, *compiled_, environment ? LightsUpdate::All : LightsUpdate::KeepEnvironment);
        device_.uploadLights(*compiled_, stream_, environment);
    });
}

void CudaBackend::fullBuild(const Scene& scene, const ProgressFn& progress, SyncReport& report) {
    CompileOptions options;
    options.bruteForce = toggles_.bruteForce;
    options.mergeSmallInstances = toggles_.mergeInstances;
    // The compressed forms (gpuWideBvh) are built behind the first frame, startCompressing().
    options.deferBlasesFrom = firstBuildOnGpu() ? kGpuFirstBuildMinPrimitives : 0u;
    auto compiled = std::make_unique<CompiledScene>(compileRenderScene(scene, options, progress));
    report.steps.push_back(
        {"compile scene (host)", compiled->stats.flattenSeconds + compiled->stats.lightSeconds});
    report.steps.push_back({compiled->deferredBlases.empty()
                                ? "build BLAS (host, binned SAH)"
                                : "build BLAS (host, binned SAH; large meshes deferred)",
                            compiled->stats.blasSeconds});
    retireSahTrees();
    compressedRefusal_.clear();
    pinnedVertices_.clear();
    compiled_ = std::move(compiled);
    // The deferred meshes' SAH trees build on threads behind the first frame, from their
    // primitives' boxes, computed here beside the upload and the GPU builds (which only read
    // the compiled geometry, as this does) rather than before them: in the compile, a 10M-
    // triangle mesh's boxes were 0.04 s of a 0.17 s first sync on an H200. Should the upload
    // throw, the future's destructor waits for them.
    std::vector<uint32_t> deferred;
    for (const DeferredBlas& d : compiled_->deferredBlases) deferred.push_back(d.blas);
    std::future<std::vector<LargeArray<Aabb>>> deferredBounds =
        std::async(std::launch::async, [this, deferred] {
            std::vector<LargeArray<Aabb>> bounds;
            for (const uint32_t blas : deferred)
                bounds.push_back(primitiveBoundsOf(*compiled_, compiled_->blases[blas]));
            return bounds;
        });
    pinnedVertices_.emplace_back(compiled_->positions.data(), compiled_->positions.size() * sizeof(Vec3));
    pinnedVertices_.emplace_back(compiled_->normals.data(), compiled_->normals.size() * sizeof(Vec3));
    pinnedVertices_.emplace_back(compiled_->tangents.data(), compiled_->tangents.size() * sizeof(Vec4));
    meshVertexOffset_.assign(scene.meshes.size(), 0);
    uint32_t vertices = 0;
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        meshVertexOffset_[i] = vertices;
        if (scene.meshes[i].kind == GeometryKind::Triangles)
            vertices += uint32_t(scene.meshes[i].positions.size());
    }
    timedStep(stream_, report, "upload", [&] { device_.uploadAll(*compiled_, stream_); });
    // Measured when a BLAS is first refitted, not here: most meshes never are.
    builtSah_.assign(device_.blasCount(), kSahUnknown);
    compressedPlan_.assign(device_.blasCount(), CompressedPlan::Take);
    if (compressesBlases()) device_.expectCompressed(stream_);
    buildDeferredBlasesOnDevice(report);
    if (!deferred.empty()) {
        std::vector<LargeArray<Aabb>> bounds;
        timedStep(stream_, report, "wait for the deferred meshes' boxes (host, beside the upload)",
                  [&] { bounds = deferredBounds.get(); });
        for (size_t i = 0; i < deferred.size(); ++i)
            pendingSahTrees_.push_back({deferred[i], std::make_unique<BackgroundBvhBuild>(
                                                         std::move(bounds[i]), toggles_.gpuWideBvh)});
    }
    skins_.clear();
    skinnedOnDevice_.assign(scene.meshes.size(), false);
    // The compile read the host's vertices of meshes whose pose the device is to skin (an
    // earlier pose): they are skinned and refitted before the first frame.
    std::vector<uint32_t> pending;
    for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
        if (pendingSkinOf(scene, i)) pending.push_back(i);
    }
    bool needsFullBuild = false;
    if (!pending.empty()) refitChangedMeshes(scene, TouchedIds::only(pending), report, needsFullBuild);
    buildTlasOnDevice(report);
    hostTlasStale_ = !pending.empty();  // else the compile built the host's TLAS too
    if (compressesBlases()) startCompressing(deferred);
}

bool CudaBackend::compressesBlases() const { return toggles_.gpuWideBvh && !toggles_.bruteForce; }

void CudaBackend::startCompressing(const std::vector<uint32_t>& deferred) {
    // The deferred meshes' forms come with their SAH trees (landSahTrees).
    std::vector<uint8_t> skip(compiled_->blases.size(), 0);
    for (const uint32_t blas : deferred) skip[blas] = 1;
    compressing_ = std::async(std::launch::async, [this, skip] {
        // An arena of its own, as BackgroundBvhBuild's: no other thread's wait steals from it.
        tbb::task_arena arena;
        return arena.execute([&] { return compressBlases(*compiled_, skip); });
    });
}

bool CudaBackend::landCompressedBlases(bool wait) {
    if (!compressing_.valid()) return false;
    if (!wait && compressing_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return false;
    CompressedBlases built;
    try {
        built = compressing_.get();
    } catch (const std::invalid_argument& e) {
        compressedRefusal_ = e.what();  // too many primitives: the binary walk stays
        return true;
    } catch (const std::bad_alloc&) {
        compressedRefusal_ = "the host ran out of memory for the compressed BVH";
        return true;
    }
    std::vector<DeviceScene::CompressedRange> ranges;
    for (uint32_t i = 0; i < compressedPlan_.size(); ++i) {
        if (compressedPlan_[i] == CompressedPlan::Skip) continue;  // its tree is not the compiled one
        const auto [firstNode, endNode] = built.nodeRange(i);
        const auto [firstPrim, endPrim] = built.primRange(i);
        ranges.push_back({i, firstNode, endNode - firstNode, firstPrim, endPrim - firstPrim});
    }
    if (!device_.appendCompressed(std::move(built.forms), ranges, stream_)) return true;
    for (uint32_t i = 0; i < compressedPlan_.size(); ++i) {
        // Built from the host's boxes: the device refitted these since (a pose skinned there).
        if (compressedPlan_[i] == CompressedPlan::Requantize) device_.requantizeCompressed(i, stream_);
    }
    return true;
}

void CudaBackend::discardCompressedBlases() {
    if (compressing_.valid()) compressing_.wait();  // it reads the compiled scene about to go
    compressing_ = {};
}

void CudaBackend::landBackgroundWork(bool wait) {
    const bool compressedLanded = landCompressedBlases(wait);
    if (!landSahTrees(wait) && !compressedLanded) return;
    PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
    updateView();  // fitting a region to its tree, or appending compressed nodes, moved buffers
}

bool CudaBackend::uploadChangedVertices(const Mesh& mesh, uint32_t meshIndex) {
    const uint32_t first = meshVertexOffset_[meshIndex], count = uint32_t(mesh.positions.size());
    // After a GPU skin, the device's vertices differ from compiled_'s wherever the pose moved
    // them: the whole mesh goes up.
    const bool whole = skinnedOnDevice_[meshIndex];
    skinnedOnDevice_[meshIndex] = false;
    auto copy = [&](auto* stored, const auto* incoming) {
        if (!whole) return copyChangedRange(stored + first, incoming, count);
        std::memcpy(stored + first, incoming, size_t(count) * sizeof(*incoming));
        return std::pair<uint32_t, uint32_t>(0u, count);
    };
    const auto positions = copy(compiled_->positions.data(), mesh.positions.data());
    device_.uploadPositions(*compiled_, first + positions.first, positions.second, stream_);
    if (mesh.normals.size() == count) {
        const auto normals = copy(compiled_->normals.data(), mesh.normals.data());
        device_.uploadNormals(*compiled_, first + normals.first, normals.second, stream_);
    }
    if (!compiled_->tangents.empty() && mesh.tangents.size() == count) {
        const auto tangents = copy(compiled_->tangents.data(), mesh.tangents.data());
        device_.uploadTangents(*compiled_, first + tangents.first, tangents.second, stream_);
    }
    return positions.second > 0;
}

std::optional<SyncAction> CudaBackend::refitChangedMeshes(const Scene& scene, const TouchedIds& meshes,
                                                          SyncReport& report, bool& needsFullBuild) {
    const uint32_t meshBlases = device_.blasCount() - (compiled_->merged.active() ? 1u : 0u);
    if (scene.meshes.size() != meshBlases) {
        needsFullBuild = true;
        return std::nullopt;
    }
    std::vector<uint32_t> changed, skinned;
    timedStep(stream_, report, "upload vertices", [&] {
        for (const uint32_t i : meshes.below(meshBlases)) {
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
                changed.push_back(i);
                continue;
            }
            if (size_t(meshVertexOffset_[i]) + mesh.positions.size() > compiled_->positions.size()) {
                needsFullBuild = true;
                return;
            }
            if (pendingSkinOf(scene, i)) {
                skinned.push_back(i);
                continue;
            }
            // Normals or tangents alone change shading, not bounds: uploaded, not refitted.
            if (uploadChangedVertices(mesh, i)) changed.push_back(i);
        }
    });
    if (needsFullBuild) return std::nullopt;
    if (!skinned.empty()) {
        timedStep(stream_, report, "skin (GPU)", [&] {
            for (const uint32_t i : skinned) {
                skins_.skin(i, *pendingSkinOf(scene, i), device_.vertices(meshVertexOffset_[i]), stream_);
                skinnedOnDevice_[i] = true;
            }
        });
        changed.insert(changed.end(), skinned.begin(), skinned.end());
    }
    if (changed.empty()) return std::nullopt;

    bool rebuilt = false;
    bool mergedCopiesChanged = false;  // a merged instance's mesh moved: its copies follow
    for (uint32_t i : changed) {
        rebuilt |= refitBlas(i, report);
        for (const MergedPiece& piece : compiled_->merged.pieces) mergedCopiesChanged |= piece.mesh == i;
    }
    PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
    if (mergedCopiesChanged && bakeMergedGeometry(scene, *compiled_)) {
        rebuilt |= refitMergedBlas(report) == SyncAction::Rebuild;
    }
    return rebuilt ? SyncAction::Rebuild : SyncAction::Refit;
}

bool CudaBackend::refitBlas(uint32_t i, SyncReport& report) {
    if (builtSah_[i] == kSahUnknown) builtSah_[i] = blasSahCost(i);  // still as built
    timedStep(stream_, report, "refit BLAS", [&] { refitToPrimitives(i); });
    if (compressedPlan_[i] == CompressedPlan::Take) compressedPlan_[i] = CompressedPlan::Requantize;
    bool rebuilt = false;
    const float cost = blasSahCost(i);
    if (cost > toggles_.rebuildSahRatio * builtSah_[i]) {
        timedStep(stream_, report, toggles_.gpuPloc ? "rebuild BLAS (GPU H-PLOC)" : "rebuild BLAS (GPU LBVH)",
                  [&] { rebuildBlasOnDevice(i); });
        builtSah_[i] = blasSahCost(i);
        retireSahTree(i);  // a tree of positions this far from the current ones is no better
        rebuilt = true;
    } else if (device_.hasCompressedForm(i)) {
        timedStep(stream_, report, "requantise BLAS (8-wide)",
                  [&] { device_.requantizeCompressed(i, stream_); });
    }
    // A tree's topology holds for any positions of its primitives: the SAH tree building
    // behind the first frame is refitted to the current ones when it lands.
    for (PendingSahTree& pending : pendingSahTrees_) pending.refitted |= !rebuilt && pending.blas == i;
    // The host keeps each BLAS's root box current (32 bytes): the host TLAS, and so the
    // scene bounds the light table uses, are built from it. Refit and rebuild give the
    // same root, the union of the primitives' boxes.
    PT_CUDA_CHECK(cudaMemcpyAsync(compiled_->blasNodes.data() + compiled_->blases[i].nodeOffset,
                                  device_.blasNodes(i), sizeof(BvhNode), cudaMemcpyDeviceToHost, stream_));
    return rebuilt;
}

void CudaBackend::refitToPrimitives(uint32_t i) {
    primBoxes_.resize(device_.blas(i).primitiveCount);
    refitVisits_.resize(device_.blasNodeCapacity(i));
    device_.prepareRefit(i, stream_);  // parent links, on a BLAS's first refit
    computePrimitiveBoxes(device_.view(*compiled_), device_.blas(i), primBoxes_.data(), stream_);
    refitBvh(device_.blasNodes(i), device_.blas(i).nodeCount, device_.blasParents(i),
             device_.blasPrimIndices(i), primBoxes_.data(), refitVisits_.data(), stream_);
}

void CudaBackend::rebuildBlasOnDevice(uint32_t i) {
    device_.reserveLbvhNodes(i, stream_);  // room for 2n - 1 nodes, on a first rebuild
    const uint32_t primitives = device_.blas(i).primitiveCount, builtNodes = lbvhNodeCount(primitives);
    // With the collapse on, the builder builds into its scratch and the collapse writes the
    // kept tree to the BLAS's place; without, the builder writes there itself.
    const BvhLeafCollapse::BuildScratch into =
        toggles_.gpuLeafCollapse
            ? leafCollapse_.buildScratch(builtNodes, primitives)
            : BvhLeafCollapse::BuildScratch{device_.blasNodes(i), device_.blasPrimIndices(i)};
    if (toggles_.gpuPloc) {
        hploc_.build(primBoxes_.data(), primitives, into.nodes, into.primIndices, stream_);
    } else {
        lbvh_.build(primBoxes_.data(), primitives, into.nodes, into.primIndices, stream_);
    }
    const uint8_t* builtChoices = toggles_.gpuPloc ? hploc_.subtreeChoices() : lbvh_.subtreeChoices();
    const uint32_t nodeCount =
        toggles_.gpuLeafCollapse
            ? leafCollapse_.collapseInto(into.nodes, builtNodes, into.primIndices, primitives,
                                         device_.blasNodes(i), device_.blasPrimIndices(i), stream_,
                                         builtChoices)
            : builtNodes;
    device_.setBlasNodeCount(i, nodeCount, stream_);
    device_.dropCompressed(i, stream_);         // the kernels walk the new tree's binary nodes
    compressedPlan_[i] = CompressedPlan::Skip;  // and its compressed form, if still to come, is stale
}

bool CudaBackend::firstBuildOnGpu(std::string* why) const {
    // With gpuWideBvh the meshes it defers walk their binary trees until their SAH trees land
    // with their compressed forms (buildCompressedBlases, landSahTrees).
    const char* reason = !toggles_.gpuFirstBuild ? "off" : toggles_.bruteForce ? "the BVH is off" : nullptr;
    if (reason && why) *why = reason;
    return reason == nullptr;
}

void CudaBackend::buildDeferredBlasesOnDevice(SyncReport& report) {
    if (compiled_->deferredBlases.empty()) return;
    const char* step = toggles_.gpuPloc ? "build BLAS (GPU H-PLOC; SAH on the host behind it)"
                                        : "build BLAS (GPU LBVH; SAH on the host behind it)";
    timedStep(stream_, report, step, [&] {
        for (const DeferredBlas& deferred : compiled_->deferredBlases) {
            primBoxes_.resize(device_.blas(deferred.blas).primitiveCount);
            computePrimitiveBoxes(device_.view(*compiled_), device_.blas(deferred.blas), primBoxes_.data(),
                                  stream_);
            rebuildBlasOnDevice(deferred.blas);
        }
    });
    compiled_->deferredBlases.clear();  // their boxes went to the SAH builds
}

bool CudaBackend::landSahTrees(bool wait) {
    staleSahTrees_.erase(
        std::remove_if(staleSahTrees_.begin(), staleSahTrees_.end(),
                       [&](const std::unique_ptr<BackgroundBvhBuild>& b) { return wait || b->finished(); }),
        staleSahTrees_.end());
    bool landed = false;
    for (auto it = pendingSahTrees_.begin(); it != pendingSahTrees_.end();) {
        PendingSahTree& pending = *it;
        if (!pending.treeLanded && (wait || pending.build->ready())) {
            const Bvh* tree = nullptr;
            try {
                tree = &pending.build->tree();
            } catch (const std::bad_alloc&) {
                // The host ran out of memory for it: the BLAS keeps its GPU build.
                it = pendingSahTrees_.erase(it);
                continue;
            }
            device_.uploadBlasTree(pending.blas, tree->nodes, tree->primIndices, stream_);
            if (pending.refitted) refitToPrimitives(pending.blas);
            builtSah_[pending.blas] = kSahUnknown;  // measured again at its next refit
            pending.treeLanded = landed = true;
        }
        // Its compressed form follows the tree, built from it on the same thread.
        if (pending.treeLanded && (wait || pending.build->finished())) {
            const PendingSahTree done = std::move(pending);  // out of the list before anything can throw
            it = pendingSahTrees_.erase(it);
            CompressedWideBvh wide = done.build->takeCompressed();
            const DeviceScene::CompressedRange range{done.blas, 0, uint32_t(wide.nodes.size()), 0,
                                                     uint32_t(wide.primIndices.size())};
            if (!wide.nodes.empty() && device_.appendCompressed(std::move(wide), {range}, stream_) &&
                done.refitted)
                device_.requantizeCompressed(done.blas, stream_);  // from the refitted binary boxes
            landed = true;
            continue;
        }
        ++it;
    }
    const bool treesToLand = std::any_of(pendingSahTrees_.begin(), pendingSahTrees_.end(),
                                         [](const PendingSahTree& p) { return !p.treeLanded; });
    if (landed && !treesToLand) {  // the first frame's build memory back (a GPU rebuild allocates it again)
        PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
        lbvh_.release();
        hploc_.release();
        leafCollapse_.release();
        primBoxes_ = {};
    }
    return landed;
}

std::optional<double> CudaBackend::finishBackgroundWork() {
    if (pendingSahTrees_.empty() && staleSahTrees_.empty() && !compressing_.valid()) return std::nullopt;
    const auto start = Clock::now();
    landBackgroundWork(true);
    return secondsSince(start);
}

void CudaBackend::retireSahTree(uint32_t blas) {
    for (auto it = pendingSahTrees_.begin(); it != pendingSahTrees_.end(); ++it) {
        if (it->blas != blas) continue;
        staleSahTrees_.push_back(std::move(it->build));
        pendingSahTrees_.erase(it);
        return;
    }
}

void CudaBackend::retireSahTrees() {
    for (PendingSahTree& pending : pendingSahTrees_) staleSahTrees_.push_back(std::move(pending.build));
    pendingSahTrees_.clear();
}

SyncAction CudaBackend::refitMergedBlas(SyncReport& report) {
    const MergedGeometry& merged = compiled_->merged;
    const uint32_t first = merged.pieces.front().firstVertex;
    timedStep(stream_, report, "upload merged vertices", [&] {
        device_.uploadPositions(*compiled_, first, uint32_t(compiled_->positions.size()) - first, stream_);
    });
    const bool rebuilt = refitBlas(merged.blas, report);
    PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
    return rebuilt ? SyncAction::Rebuild : SyncAction::Refit;
}

// Up to this many instances, the TLAS is built on the host with binned SAH (a few microseconds
// for a room of objects) and uploaded; beyond, on the GPU as an LBVH, whose cost stays in
// proportion to the instances on any scale. SAH places few, unevenly sized instances (walls
// around small objects) better than Morton order does, and CPU and GPU then walk one tree.
// Measured on the H100 at 1080p (spp/s, LBVH / host SAH TLAS): Cornell box wavefront 216 / 221,
// megakernel 99 / 102; Balloon megakernel 327 / 345.
constexpr size_t kHostTlasMaxInstances = 256;

void CudaBackend::buildTlasOnDevice(SyncReport& report) {
    const size_t instances = compiled_->instances.size();
    // The GPU build boxes every instance; with a merged BLAS the TLAS holds other entries.
    if (compiled_->merged.active() || (instances > 1 && instances <= kHostTlasMaxInstances)) {
        timedStep(stream_, report, "build TLAS (host SAH)", [&] {
            pt::buildTlas(*compiled_);
            hostTlasStale_ = false;
            device_.uploadTlas(*compiled_, stream_);
        });
        return;
    }
    timedStep(stream_, report, "build TLAS (GPU LBVH)",
              [&] { device_.buildTlas(lbvh_, primBoxes_, stream_); });
}

float CudaBackend::blasSahCost(uint32_t blas) const {
    return sahCostOnDevice(device_.blasNodes(blas), device_.blas(blas).nodeCount, stream_);
}

void CudaBackend::updateView() {
    view_ = device_.view(*compiled_);  // bruteForce comes from the compile options
    applyIntegratorToggles(toggles_, view_.settings);
}

void CudaBackend::setToggles(const IntegratorToggles& toggles) {
    const bool bvhChanged = toggles.bruteForce != toggles_.bruteForce ||
                            toggles.mergeInstances != toggles_.mergeInstances ||
                            toggles.gpuWideBvh != toggles_.gpuWideBvh;
    toggles_ = toggles;
    if (bvhChanged) {  // the next sync recompiles (and checks the budget)
        discardCompressedBlases();
        retireSahTrees();
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
    if (runsMegakernel())
        reason = "the megakernel traces every ray itself";
    else if (toggles_.pixelJitter)
        reason = "pixel jitter is on, so camera rays differ per sample";
    else if (compiled_ && compiled_->camera.lensRadius > 0.0f)
        reason = "the thin lens moves camera rays per sample";
    if (reason && why) *why = reason;
    return reason == nullptr;
}

ScheduleOptions CudaBackend::scheduleOptions() const {
    ScheduleOptions o;
    o.megakernel = runsMegakernel();
    o.regeneration = toggles_.pathRegeneration;
    o.compaction = toggles_.streamCompaction;
    o.materialSort = toggles_.materialSort;
    o.firstHitCache = toggles_.firstHitCache && firstHitCacheApplies(nullptr);
    o.materialCount = compiled_ ? uint32_t(compiled_->materials.size()) : 1u;
    o.kernelVariant = kernelVariantIndex(toggles_.kernelVariant);
    return o;
}

void CudaBackend::resetAccumulation() {
    sum_.resize(size_t(width_) * height_ * 3);
    sum_.fillZero(stream_);
    aovs_ = AovSet{aovsRequested_, {}};
    const size_t aovDoubles = aovDoublesPerPixel(aovs_.mask) * width_ * height_;
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

FeatureSet CudaBackend::renderFeatures() const {
    return view_.features | (aovs_.mask != 0 ? feature::kAovs : 0u);
}

AovMask CudaBackend::recordingAovs() const { return aovs_.recording(aovSampleCap(), stats_.samplesPerPixel); }

PassSchedule CudaBackend::nextPass() const {
    if (toggles_.autoSchedule) return scheduleChooser_.next();
    return {toggles_.megakernel, true};  // the compressed nodes wherever the scene has them
}

uint64_t CudaBackend::scheduleKey(uint32_t samplesPerWave) const {
    // What decides which schedule is faster: the kernel's features, the image, the path length,
    // the toggles that change the work and the size of a wave (in powers of two). FNV-1a over
    // them.
    const IntegratorSettings& s = view_.settings;
    uint32_t waveClass = 0;
    while ((samplesPerWave >> (waveClass + 1)) != 0) ++waveClass;
    const FeatureSet features = renderFeatures();
    const uint32_t words[] = {uint32_t(features),
                              (recordingAovs() & kPathAovs) != 0,  // the generic AOV kernel or not
                              uint32_t(features >> 32),
                              waveClass,
                              s.width,
                              s.height,
                              s.maxDepth,
                              s.nextEventEstimation,
                              s.russianRoulette,
                              s.pixelJitter,
                              toggles_.streamCompaction,
                              toggles_.materialSort,
                              toggles_.firstHitCache,
                              hasCompressedNodes()};
    uint64_t h = 1469598103934665603ull;
    for (const uint32_t w : words) h = (h ^ w) * 1099511628211ull;
    return h;
}

// One wave at a time, each waited for: the interrupt flag is read between waves, so an edit
// waits for one wave, not the call's; and the auto schedule's trial times each wave it runs.
void CudaBackend::render(uint32_t passes) {
    if (!compiled_ || passes == 0) return;
    const auto start = Clock::now();
    const uint32_t wave = scheduler_.samplesPerWave(width_ * height_, passes);
    // The trial runs waves of the size this call runs, alternating the schedules, until both
    // have run theirs.
    while (passes > 0) {
        if (interruptRequested()) {
            resetAccumulation();
            return;
        }
        // Between waves, not only between calls: a call of the CLI's lasts a quarter second,
        // and the first frame's GPU trees cost more to walk than the SAH trees.
        landBackgroundWork(false);
        // Per wave (its key says whether path AOVs record): a capped AOV stops where a wave
        // ends at its cap, and from then on the scene's specialised kernels run where no other
        // path AOV records.
        if (toggles_.autoSchedule) scheduleChooser_.setKey(scheduleKey(wave), hasCompressedNodes());
        const bool trial = toggles_.autoSchedule && !scheduleChooser_.decided();
        const PassSchedule pass = nextPass();
        // The binary walk: the kernels walk a BLAS's binary nodes where it has no compressed root.
        RenderScene scene = view_;
        if (!pass.compressedWalk) scene.blasCompressedRoots = {};
        const uint32_t n =
            std::min({wave, passes, aovs_.samplesUntilFull(aovSampleCap(), stats_.samplesPerPixel)});
        const AovMask recording = recordingAovs();
        const AovBuffers aovs = aovBuffersIn(aovSums_.data(), aovs_, size_t(width_) * height_, recording);
        const auto waveStart = Clock::now();
        scheduler_.render(scene, stats_.samplesPerPixel, n, scheduleOptions(), sum_.data(), aovs, stream_);
        PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
        if (trial) scheduleChooser_.record(pass, secondsSince(waveStart) / n);
        aovs_.skip(recording, n);
        stats_.samplesPerPixel += n;
        passes -= n;
    }
    stats_.renderSeconds += secondsSince(start);
}

void CudaBackend::readBeauty(std::vector<float>& rgba) const {
    const std::vector<double> sum = sum_.download();
    meanImageFromSums(sum.data(), size_t(width_) * height_, stats_.samplesPerPixel, rgba);
}

std::vector<uint32_t> CudaBackend::pathsAlivePerBounce() const {
    return runsMegakernel() ? std::vector<uint32_t>{} : scheduler_.pathsPerBounce();
}

std::string CudaBackend::deviceName() const { return deviceInfo().name; }

KernelFigures CudaBackend::kernelFigures() const {
    KernelFigures figures;
    for (const KernelVariant& v : kKernelVariants) figures.variants.push_back({v.name, v.features});
    figures.kernels = kernelResources();
    return figures;
}

std::shared_ptr<void> CudaBackend::allocateDeviceFrame() const {
    void* memory = nullptr;
    if (cudaMalloc(&memory, size_t(width_) * height_ * 4 * sizeof(float)) != cudaSuccess) {
        cudaGetLastError();  // clear it: later calls must not see it
        return nullptr;
    }
    return std::shared_ptr<void>(memory, [](void* p) { cudaFree(p); });
}

std::optional<DeviceBvhFigures> CudaBackend::measureDeviceBvh(const BvhBuildInput& input, uint32_t runs) {
    if (input.meshBoxes.empty()) return std::nullopt;
    return measureDeviceBvhBuilds(input, runs, stream_);
}

bool CudaBackend::copyBeautyToDevice(void* deviceRgba) const {
    launchMeanToRgba(sum_.data(), size_t(width_) * height_, stats_.samplesPerPixel,
                     static_cast<float*>(deviceRgba), stream_);
    PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
    return true;
}

void CudaBackend::readAov(Aov aov, std::vector<float>& rgba) const {
    requireAov(aovs_.mask, aov);
    const size_t pixels = size_t(width_) * height_;
    std::vector<double> plane(pixels * aovChannels(aov));
    aovSums_.downloadAt(aovPlaneOffset(aovs_.mask, aov, pixels), plane.data(), plane.size());
    aovImageFromSums(aov, plane.empty() ? nullptr : plane.data(), pixels, aovSamples(aov),
                     stats_.samplesPerPixel, rgba);
}

void CudaBackend::changeAovs(AovMask aovs) {
    aovsRequested_ = aovs;
    if (aovs == aovs_.mask) return;
    const size_t pixels = size_t(width_) * height_;
    DeviceBuffer<double> sums(aovDoublesPerPixel(aovs) * pixels);
    sums.fillZero(stream_);
    for (const AovPlaneMove& m : keptAovPlanes(aovs_.mask, aovs, pixels)) {
        PT_CUDA_CHECK(cudaMemcpyAsync(sums.data() + m.to, aovSums_.data() + m.from,
                                      m.doubles * sizeof(double), cudaMemcpyDeviceToDevice, stream_));
    }
    PT_CUDA_CHECK(cudaStreamSynchronize(stream_));
    aovSums_ = std::move(sums);
    aovs_ = aovs_.changedTo(aovs, stats_.samplesPerPixel);
}

bool CudaBackend::copyDenoisedToDevice(void* deviceRgba, double* seconds) const {
    requireDenoiseGuides(*this);
    const AovBuffers aovs = aovBuffersIn(aovSums_.data(), aovs_, size_t(width_) * height_);
    StreamTimer timer;
    const double s = timer.time(stream_, [&] {
        denoiser_.run(sum_.data(), aovs, aovs_.samplesAt(stats_.samplesPerPixel), width_, height_,
                      stats_.samplesPerPixel, static_cast<float*>(deviceRgba), stream_);
    });
    if (seconds) *seconds = s;
    return true;
}

double CudaBackend::readDenoised(std::vector<float>& rgba) const {
    const size_t pixels = size_t(width_) * height_;
    if (denoised_.size() != 4 * pixels) denoised_ = DeviceBuffer<float>(4 * pixels);
    double seconds = 0.0;
    copyDenoisedToDevice(denoised_.data(), &seconds);
    denoised_.download(rgba);
    return seconds;
}

uint64_t CudaBackend::aovBytes() const { return aovSums_.bytes() + scheduler_.aovBytes(); }

BackendStats CudaBackend::stats() const {
    BackendStats s = stats_;
    const RenderCounters counters = scheduler_.counters();
    s.rays = counters.rays;
    s.nonfiniteSamples = counters.nonfinite;
    s.features = renderFeatures();
    // As the scheduler chooses (AOVs aside: their code runs in kernels of its own).
    const KernelVariant& variant =
        kKernelVariants[chooseKernelVariant(view_.features, kernelVariantIndex(toggles_.kernelVariant))];
    s.kernelVariant = variant.name;
    s.kernelFeatures = variant.features;
    if (toggles_.autoSchedule) {
        s.schedule = scheduleChooser_.choice();
        s.megakernelRate = scheduleChooser_.megakernelRate();
        s.wavefrontRate = scheduleChooser_.wavefrontRate();
        s.walk = scheduleChooser_.walkChoice();
    } else {
        s.schedule = toggles_.megakernel ? "megakernel" : "wavefront";
        s.walk = hasCompressedNodes() ? "compressed" : "";
    }
    return s;
}

std::vector<ToggleState> CudaBackend::toggleStates() const {
    std::vector<ToggleState> states = integratorToggleStates(toggles_);
    for (ToggleState& s : states) {
        if (!s.requested) continue;
        if (s.id == ToggleId::FirstHitCache) {
            s.active = firstHitCacheApplies(&s.note);
        } else if ((s.id == ToggleId::Compaction || s.id == ToggleId::MaterialSort) && runsMegakernel()) {
            s.active = false;
            s.note = "wavefront only; the megakernel is on";
        } else if (s.id == ToggleId::PathRegeneration && !runsMegakernel()) {
            s.active = false;
            s.note = "megakernel only; the wavefront is on";
        } else if (s.id == ToggleId::GpuWideBvh && !compressedRefusal_.empty()) {
            s.active = false;
            s.note = compressedRefusal_;
        } else if (s.id == ToggleId::GpuFirstBuild) {
            s.active = firstBuildOnGpu(&s.note);
        } else if (s.id == ToggleId::WideBvh) {
            s.active = false;
            s.note = "CPU only: the GPU's wide BVH is gpu_wide_bvh";
        } else if (s.id == ToggleId::RayPackets) {
            s.active = false;
            s.note = "CPU only: a warp already walks 32 rays together";
        } else if (s.id == ToggleId::PathRegeneration && (recordingAovs() & kPathAovs) != 0) {
            s.active = false;
            s.note = "path AOVs run one path a thread";
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
    if (queryClaims_.size() == 0) {
        queryClaims_.resize(1);
        queryClaims_.fillZero(stream_);
    }
    StreamTimer timer;
    for (uint32_t run = 0; run < runs; ++run) {
        seconds.push_back(timer.time(stream_, [&] {
            launchTraceRays(view_, queryRays_.data(), uint32_t(rays.size()), anyHit, queryHits_.data(),
                            queryClaims_.data(), stream_);
        }));
    }
    if (hits) queryHits_.download(*hits);
    return seconds;
}

std::vector<std::pair<std::string, uint64_t>> CudaBackend::deviceMemoryByBuffer() const {
    std::vector<std::pair<std::string, uint64_t>> rows = device_.buffers();
    rows.emplace_back("path scheduler", scheduler_.bytes());
    rows.emplace_back("accumulation (beauty)", sum_.bytes());
    rows.emplace_back("accumulation (AOVs)", aovSums_.bytes());
    rows.emplace_back("denoiser", denoiser_.bytes() + denoised_.bytes());
    rows.emplace_back("skins (bind poses, joints)", skins_.bytes());
    rows.emplace_back("BVH scratch (primitive boxes)", primBoxes_.bytes());
    rows.emplace_back("BVH scratch (refit visits)", refitVisits_.bytes());
    rows.emplace_back("BVH scratch (LBVH builder)", lbvh_.bytes());
    rows.emplace_back("BVH scratch (H-PLOC builder)", hploc_.bytes());
    rows.emplace_back("BVH scratch (leaf collapse)", leafCollapse_.bytes());
    rows.emplace_back("ray queries", queryRays_.bytes() + queryHits_.bytes() + queryClaims_.bytes());
    return rows;
}

uint64_t CudaBackend::deviceMemoryBytes() const {
    uint64_t total = 0;
    for (const auto& row : deviceMemoryByBuffer()) total += row.second;
    return total;
}

}  // namespace pt::cuda
