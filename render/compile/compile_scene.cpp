#include "render/compile/compile_scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/instance_bounds.h"
#include "render/bvh/wide_bvh.h"
#include "render/compile/compile_geometry.h"
#include "render/compile/scene_features.h"
#include "render/compile/wide_blases.h"
#include "render/integrator/camera.h"
#include "render/materials/alpha.h"
#include "render/util/stopwatch.h"

namespace pt {

namespace {

template <class T>
Span<const T> spanOf(const std::vector<T>& v) {
    return {v.data(), uint32_t(v.size())};
}

void compileTextures(const Scene& scene, CompiledScene& out) {
    for (const Texture& t : scene.textures) {
        TextureView view{};
        view.width = t.width;
        view.height = t.height;
        view.format = t.format;
        view.wrapS = t.wrapS;
        view.wrapT = t.wrapT;
        view.nearest = t.nearest ? 1u : 0u;
        if (t.format == TexelFormat::RGBA8) {
            view.texelOffset = uint32_t(out.texels8.size() / 4);
            out.texels8.insert(out.texels8.end(), t.texels8.begin(), t.texels8.end());
        } else {
            view.texelOffset = uint32_t(out.texelsF.size() / 4);
            out.texelsF.insert(out.texelsF.end(), t.texelsF.begin(), t.texelsF.end());
        }
        out.textures.push_back(view);
    }
}

}  // namespace

bool isTracedInstance(const Scene& scene, size_t i) {
    const Instance& instance = scene.instances[i];
    return instance.visible && instance.mesh < scene.meshes.size() &&
           scene.meshes[instance.mesh].primitiveCount() > 0;
}

int32_t sceneInstanceOfHit(const CompiledScene& compiled, uint32_t r) {
    return r < compiled.sceneInstanceOf.size() ? int32_t(compiled.sceneInstanceOf[r]) : -1;
}

bool compileInstances(const Scene& scene, CompiledScene& out) {
    const std::vector<Material>& materials = out.materials;
    // Built aside and swapped in, so that a refused instance leaves `out` as it was.
    std::vector<RenderInstance> instances;
    std::vector<uint32_t> instanceMaterials, sceneInstanceOf,
        renderInstanceOf(scene.instances.size(), kNotTraced);
    instances.reserve(scene.instances.size());
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& src = scene.instances[i];
        if (!src.visible) continue;
        if (src.mesh >= scene.meshes.size()) {
            throw std::invalid_argument("instance \"" + src.name + "\" names mesh " +
                                        std::to_string(src.mesh) + ", which does not exist");
        }
        if (!isTracedInstance(scene, i)) continue;
        const Mesh& mesh = scene.meshes[src.mesh];
        RenderInstance inst{};
        inst.objectToWorld = src.objectToWorld;
        inst.worldToObject = inverse(src.objectToWorld);
        inst.blas = src.mesh;
        inst.flipsWinding = src.objectToWorld.determinant() < 0.0f ? 1u : 0u;
        inst.tracedInWorldSpace =
            i < out.merged.sceneInstanceMerged.size() && out.merged.sceneInstanceMerged[i];
        inst.materialOffset = uint32_t(instanceMaterials.size());
        // The last material is the fallback for slots an instance leaves unmapped.
        const uint32_t fallback = uint32_t(materials.size() - 1);
        for (uint32_t slot = 0; slot < mesh.slotCount; ++slot) {
            const uint32_t m = slot < src.materials.size() ? src.materials[slot] : fallback;
            if (m >= materials.size()) {
                throw std::invalid_argument("instance \"" + src.name + "\" names material " +
                                            std::to_string(m) + ", which does not exist");
            }
            instanceMaterials.push_back(m);
        }
        renderInstanceOf[i] = uint32_t(instances.size());
        sceneInstanceOf.push_back(uint32_t(i));
        instances.push_back(inst);
    }
    out.instances.swap(instances);
    out.instanceMaterials.swap(instanceMaterials);
    out.sceneInstanceOf.swap(sceneInstanceOf);
    out.renderInstanceOf.swap(renderInstanceOf);
    out.stats.instanceCount = uint32_t(out.instances.size());
    out.stats.instancedTriangles = 0;
    for (const RenderInstance& inst : out.instances) {
        if (out.blases[inst.blas].kind == GeometryKind::Triangles) {
            out.stats.instancedTriangles += out.blases[inst.blas].primitiveCount;
        }
    }
    return bakeMergedGeometry(scene, out);
}

void buildTlas(CompiledScene& out) {
    // The entries: instances traced through their own BLAS, then the merged BLAS.
    std::vector<Aabb> bounds;
    std::vector<uint32_t> entries;
    for (size_t i = 0; i < out.instances.size(); ++i) {
        const RenderInstance& inst = out.instances[i];
        if (inst.tracedInWorldSpace) continue;
        bounds.push_back(instanceBounds(out.blasNodes[out.blases[inst.blas].nodeOffset], inst.objectToWorld));
        entries.push_back(uint32_t(i));
    }
    if (out.merged.active()) {
        bounds.push_back(
            instanceBounds(out.blasNodes[out.blases[out.merged.blas].nodeOffset], Affine3{}));  // identity
        entries.push_back(uint32_t(out.instances.size()));
    }
    // One instance a leaf, as the GPU APIs' instance BVHs have it: testing an instance costs an
    // object-space ray and a BLAS walk, far more than the box test a leaf of its own adds.
    BvhBuildOptions options;
    options.maxLeafSize = 1;
    Bvh tlas = buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size()), options);
    out.tlasNodes = std::move(tlas.nodes);
    out.tlasInstanceIndices = std::move(tlas.primIndices);
    for (uint32_t& index : out.tlasInstanceIndices) index = entries[index];
    // Beside 8-wide BLASes, the CPU walks an 8-wide TLAS too (wide_bvh.h), its leaves the
    // binary ones.
    out.tlasWideNodes.clear();
    if (!out.blasWideRoots.empty())
        out.tlasWideNodes = collapseToWide(out.tlasNodes.data(), uint32_t(out.tlasNodes.size())).nodes;
}

std::vector<Material> compileMaterials(const Scene& scene) {
    std::vector<Material> materials;
    materials.reserve(scene.materials.size() + 1);
    for (const NamedMaterial& m : scene.materials) materials.push_back(m.params);
    materials.push_back(Material{});  // fallback for unmapped slots
    return materials;
}

IntegratorSettings compileSettings(const RenderSettings& settings) {
    IntegratorSettings s{};
    s.width = settings.width;
    s.height = settings.height;
    s.maxDepth = settings.maxDepth;
    s.seed = settings.seed;
    return s;
}

RenderEnvironment compileEnvironment(const Environment& environment) {
    RenderEnvironment env{};
    env.color = environment.color * environment.intensity;
    env.texture = environment.texture;
    env.intensity = environment.intensity;
    env.rotationRadians = environment.rotationDegrees * kPi / 180.0f;
    return env;
}

void updateTransparency(CompiledScene& out) {
    out.transparentMaterials = false;
    for (const Material& m : out.materials) out.transparentMaterials |= materialMayLetRaysThrough(m);
}

PunctualLight compilePunctualLight(const Light& light) {
    PunctualLight p{};
    p.type = light.type;
    p.position = light.position;
    const float len = length(light.direction);
    p.direction = len > 0.0f && std::isfinite(len) ? light.direction / len : Vec3(0.0f, 0.0f, -1.0f);
    p.intensity = light.color * light.intensity;
    const float toRadians = kPi / 180.0f;
    const float outer = std::clamp(light.outerConeDegrees, 0.0f, 90.0f) * toRadians;
    const float inner = std::clamp(light.innerConeDegrees, 0.0f, 90.0f) * toRadians;
    p.cosOuter = std::cos(outer);
    p.cosInner = std::cos(std::min(inner, outer));
    return p;
}

void compileLights(const Scene& scene, CompiledScene& out, LightsUpdate update) {
    out.punctualLights.clear();
    for (const Light& light : scene.lights) out.punctualLights.push_back(compilePunctualLight(light));
    out.environment = compileEnvironment(scene.environment);
    if (update == LightsUpdate::All) out.environmentDistribution = {};
    if (out.environment.texture >= 0) {
        if (size_t(out.environment.texture) >= scene.textures.size()) {
            throw std::invalid_argument("the environment names texture " +
                                        std::to_string(out.environment.texture) + ", which does not exist");
        }
        if (update == LightsUpdate::All && out.environment.intensity > 0.0f) {
            const Texture& image = scene.textures[size_t(out.environment.texture)];
            out.environmentDistribution = buildEnvironmentDistribution(image);
        }
        out.environment.distWidth = out.environmentDistribution.width;
        out.environment.distHeight = out.environmentDistribution.height;
    }
    out.emitters = buildEmitterTable(out.view(), out.environmentDistribution.averageLuminance);
    out.environment.lightWeight = out.emitters.environmentWeight;
    out.stats.emitterCount = out.emitters.triangles;
    out.stats.sphereLightCount = out.emitters.spheres;
    out.stats.punctualLightCount = out.emitters.punctual;
    out.stats.environmentSampled = out.emitters.environmentWeight > 0.0f;
}

CompiledScene compileRenderScene(const Scene& scene, const CompileOptions& options,
                                 const ProgressFn& progress) {
    CompiledScene out;
    auto start = Clock::now();
    out.materials = compileMaterials(scene);
    flattenGeometry(scene, out);
    if (options.mergeSmallInstances && !options.bruteForce) planMergedGeometry(scene, out);
    compileTextures(scene, out);
    compileInstances(scene, out);
    out.stats.flattenSeconds = secondsSince(start);

    if (options.bruteForce && out.stats.instancedTriangles > options.bruteForceBudget) {
        throw std::invalid_argument("BVH off (brute force) refused: the scene traces " +
                                    std::to_string(out.stats.instancedTriangles) +
                                    " triangles, over the budget of " +
                                    std::to_string(options.bruteForceBudget));
    }
    out.bruteForce = options.bruteForce;

    start = Clock::now();
    buildBlases(out, progress, options.bruteForce ? 0u : options.deferBlasesFrom);
    if (options.wideBvh && !options.bruteForce) buildWideBlases(out);
    if (options.compressedWideBvh && !options.bruteForce) buildCompressedBlases(out);
    out.stats.blasSeconds = secondsSince(start);

    start = Clock::now();
    buildTlas(out);
    out.stats.tlasSeconds = secondsSince(start);

    updateTransparency(out);

    start = Clock::now();
    compileLights(scene, out);
    out.stats.lightSeconds = secondsSince(start);

    out.camera = makeRenderCamera(scene.camera, scene.render.width, scene.render.height);
    out.settings = compileSettings(scene.render);
    updateFeatures(scene, out);
    return out;
}

void updateFeatures(const Scene& scene, CompiledScene& out) {
    bool morphTargets = false;
    for (const Mesh& mesh : scene.meshes) morphTargets |= !mesh.morphTargets.empty();
    out.features = sceneFeatures(out, morphTargets);
}

RenderScene CompiledScene::view() const {
    RenderScene s;
#define PT_SCENE_ARRAY(Type, name, label) s.name = spanOf(name);
#define PT_SCENE_LIGHT_ARRAY(Type, name, compiledMember, label) s.name = spanOf(compiledMember);
#include "render/kernel/scene_arrays.h"
    s.mergedBlas = merged.active() ? merged.blas : kNoMergedBlas;
    s.transparentMaterials = transparentMaterials ? 1u : 0u;
    s.emitterTotalWeight = emitters.totalWeight;
    s.environment = environment;
    s.camera = camera;
    s.settings = settings;
    s.bruteForce = bruteForce ? 1u : 0u;
    s.features = features;
    return s;
}

}  // namespace pt
