#pragma once
// compileRenderScene: the one place that knows both scene forms (STYLE.md rule 5). It flattens
// a Scene into arrays, builds a BLAS per mesh (binned SAH) and the TLAS over visible
// instances, gathers the emitters, and hands out a RenderScene view of it all.
#include <cstdint>
#include <string>
#include <vector>

#include "render/lights/emitter_table.h"
#include "render/lights/environment_distribution.h"
#include "render/scene/merged_geometry.h"
#include "render/scene/render_scene.h"
#include "render/scene/scene.h"
#include "render/util/progress.h"

namespace pt {

struct CompileOptions {
    bool bruteForce = false;             // no BVH: validation only
    bool mergeSmallInstances = true;     // merged_geometry.h (never with bruteForce)
    uint64_t bruteForceBudget = 100000;  // triangles x instances above which bruteForce is refused
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

struct CompiledScene {
    std::vector<Vec3> positions, normals;
    std::vector<Vec2> uvs;
    std::vector<Vec4> tangents;  // parallel to positions, or empty when no mesh has any
    std::vector<TriangleIndices> triangles;
    std::vector<Vec4> spheres;
    std::vector<uint32_t> triangleSlots, sphereSlots;
    std::vector<BlasRef> blases;
    std::vector<BvhNode> blasNodes;
    std::vector<uint32_t> blasPrimIndices;
    std::vector<RenderInstance> instances;
    std::vector<BvhNode> tlasNodes;
    std::vector<uint32_t> tlasInstanceIndices;
    MergedGeometry merged;                        // which instances the merged BLAS holds
    std::vector<MergedTriangle> mergedTriangles;  // its hit map, per merged triangle
    std::vector<uint32_t> instanceMaterials;
    std::vector<Material> materials;
    std::vector<TextureView> textures;
    std::vector<uint8_t> texels8;
    std::vector<float> texelsF;
    bool transparentMaterials = false;
    EmitterTable emitters;
    std::vector<PunctualLight> punctualLights;
    EnvironmentDistribution environmentDistribution;
    RenderEnvironment environment{};
    RenderCamera camera{};
    IntegratorSettings settings{};
    bool bruteForce = false;
    FeatureSet features = 0;  // sceneFeatures() as of the last compile or edit
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
// Whether compileInstances gives scene instance `i` a RenderInstance (visible, not empty):
// the traced instances are these, in scene order, so a Hit's instance maps back through it.
bool isTracedInstance(const Scene& scene, size_t i);
// The TLAS (binned SAH over instance world boxes, from each BLAS's root box) for compiled
// instances and BLASes: merged instances have no entry of their own, the merged BLAS one
// (index instances.size()). O(instances log instances).
void buildTlas(CompiledScene& out);
// CompiledScene::features (scene_features.h) from the compiled scene; after every edit.
void updateFeatures(const Scene& scene, CompiledScene& out);
// CompiledScene::transparentMaterials from its materials (after a material edit).
void updateTransparency(CompiledScene& out);

}  // namespace pt
