#pragma once
// compileRenderScene: the one place that knows both scene forms (STYLE.md rule 5). It flattens
// a Scene into arrays, builds a BLAS per mesh (binned SAH) and the TLAS over visible
// instances, gathers the emitters, and hands out a RenderScene view of it all.
#include <cstdint>
#include <string>
#include <vector>

#include "render/bvh/aabb.h"
#include "render/compile/merged_geometry.h"
#include "render/kernel/render_scene.h"
#include "render/lights/emitter_table.h"
#include "render/lights/environment_distribution.h"
#include "render/scene/scene.h"
#include "render/util/progress.h"

namespace pt {

struct CompileOptions {
    bool bruteForce = false;          // no BVH: validation only
    bool mergeSmallInstances = true;  // merged_geometry.h (never with bruteForce)
    bool wideBvh = false;             // the CPU's 8-wide BLASes too (wide_blases.h)
    // The GPU's compressed 8-wide BLASes too (wide_blases.h): for tests of the host's walk of
    // them; the CUDA backend collapses them behind its first frame instead.
    bool compressedWideBvh = false;
    uint64_t bruteForceBudget = 100000;  // triangles x instances above which bruteForce is refused
    // Meshes of at least this many primitives get a stand-in BLAS (one leaf over them all) and
    // a CompiledScene::deferredBlases entry, for the caller to build the tree elsewhere (the
    // CUDA backend: an LBVH on the GPU now, the SAH tree on a thread behind it). 0: every BLAS
    // is built here.
    uint32_t deferBlasesFrom = 0;
};

// A mesh BLAS whose tree compileRenderScene left to its caller (CompileOptions::deferBlasesFrom):
// its nodes are one leaf over all its primitives (exact, as brute force is), whose box is the
// tree's root box, and its primitive index list is 0 .. n - 1. The caller's build takes the
// primitives' boxes from primitiveBoundsOf (compile_geometry.h): the CUDA backend computes them
// beside its upload, off the way to the first frame.
struct DeferredBlas {
    uint32_t blas;
};

struct CompileStats {
    double flattenSeconds = 0, blasSeconds = 0, tlasSeconds = 0, lightSeconds = 0;
    uint64_t meshTriangles = 0;       // unique triangles over meshes (what BLASes hold)
    uint64_t instancedTriangles = 0;  // over visible instances (what is traced)
    uint64_t spheres = 0;
    uint32_t blasCount = 0, instanceCount = 0;
    uint32_t emitterCount = 0;  // emissive triangles NEE samples
    uint32_t sphereLightCount = 0, punctualLightCount = 0;
    bool environmentSampled = false;  // the environment is in the light table
    uint64_t blasNodes = 0;
};

// CompiledScene::renderInstanceOf for a scene instance that is not traced (hidden or empty).
constexpr uint32_t kNotTraced = 0xffffffffu;

struct CompiledScene {
    // The arrays RenderScene points at (render/kernel/scene_arrays.h), but for the light
    // table's and the environment distribution's, which `emitters` and
    // `environmentDistribution` hold.
#define PT_SCENE_ARRAY(Type, name, label) std::vector<Type> name;
#define PT_SCENE_LIGHT_ARRAY(Type, name, compiledMember, label)
#include "render/kernel/scene_arrays.h"

    MergedGeometry merged;  // which instances the merged BLAS holds
    // Per slot of blasWideNodes: the binary node it was collapsed from (wide_bvh.h), so a
    // refit refreshes the wide boxes.
    std::vector<uint32_t> wideSourceNodes;
    // Per BLAS, its first block in blasTriangleBlocks (a sphere BLAS has none), so a refit
    // refreshes its blocks' corners.
    std::vector<uint32_t> blasFirstTriangleBlock;
    // The same per slot of blasCompressedNodes (compressed_wide_bvh.h), relative to each BLAS's
    // first binary node.
    std::vector<uint32_t> compressedSourceNodes;
    // Which scene instance each traced one is (compileInstances keeps the traced instances in
    // scene order): sceneInstanceOf[r] is the Scene::instances index of instances[r], and
    // renderInstanceOf[i] that of scene instance i in instances, or kNotTraced.
    std::vector<uint32_t> sceneInstanceOf, renderInstanceOf;
    bool transparentMaterials = false;
    EmitterTable emitters;
    EnvironmentDistribution environmentDistribution;
    RenderEnvironment environment{};
    RenderCamera camera{};
    IntegratorSettings settings{};
    bool bruteForce = false;
    std::vector<DeferredBlas> deferredBlases;  // empty unless CompileOptions::deferBlasesFrom
    FeatureSet features = 0;                   // sceneFeatures() as of the last compile or edit
    CompileStats stats;

    // The view stays valid while this object lives and its vectors are not resized.
    RenderScene view() const;
};

// Throws std::invalid_argument with a clear message when a request cannot be honoured
// (brute force over its budget, an instance naming a missing mesh or material).
CompiledScene compileRenderScene(const Scene& scene, const CompileOptions& options = {},
                                 const ProgressFn& progress = {});

// The parts that edits recompile on their own.
std::vector<Material> compileMaterials(const Scene& scene);
IntegratorSettings compileSettings(const RenderSettings& settings);
RenderEnvironment compileEnvironment(const Environment& environment);
// What compileLights rebuilds. KeepEnvironment reuses the environment image's sampling
// distribution (O(pixels) to build) where only lights, transforms or geometry changed.
enum class LightsUpdate { All, KeepEnvironment };
// Punctual lights, the environment's sampling distribution and the light table, for a
// CompiledScene whose geometry, materials and TLAS are already compiled (after an edit of
// the environment or the lights). Costs O(instances x slots + lights + the primitives of
// meshes some instance shades with an emissive material): a scene without emissive surfaces
// never walks its triangles. Throws std::invalid_argument for an environment naming a
// missing texture.
void compileLights(const Scene& scene, CompiledScene& out, LightsUpdate update = LightsUpdate::All);
PunctualLight compilePunctualLight(const Light& light);
// The visible instances with their material slots, and the instance statistics, for a
// CompiledScene whose geometry and materials are compiled (after a transform or visibility
// edit); the merged instances' world-space copies are rewritten (bakeMergedGeometry). Returns
// whether those changed (the merged BLAS then needs a refit). O(instances x slots + merged
// vertices). Throws std::invalid_argument for an instance naming a missing mesh or material,
// and then leaves `out` as it was.
bool compileInstances(const Scene& scene, CompiledScene& out);
// Whether compileInstances gives scene instance `i` a RenderInstance (visible, not empty).
bool isTracedInstance(const Scene& scene, size_t i);
// The Scene::instances index of render instance `r` (a Hit's instance), or -1 past the end.
int32_t sceneInstanceOfHit(const CompiledScene& compiled, uint32_t r);
// The TLAS (binned SAH over instance world boxes, from each BLAS's root box) for compiled
// instances and BLASes: merged instances have no entry of their own, the merged BLAS one
// (index instances.size()). O(instances log instances).
void buildTlas(CompiledScene& out);
// CompiledScene::features (scene_features.h) from the compiled scene; after every edit.
void updateFeatures(const Scene& scene, CompiledScene& out);
// CompiledScene::transparentMaterials from its materials (after a material edit).
void updateTransparency(CompiledScene& out);

}  // namespace pt
