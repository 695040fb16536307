#include "render/lights/emitter_table.h"

#include <algorithm>
#include <cmath>

#include "render/lights/light_sample.h"
#include "render/sampling/alias_table_builder.h"

namespace pt {

namespace {

// Adds `e` unless its weight is zero or not finite; returns whether it did.
bool addEmitter(EmitterTable& table, std::vector<float>& weights, Emitter e) {
    if (!(e.weight > 0.0f) || !std::isfinite(e.weight)) return false;
    table.emitters.push_back(e);
    weights.push_back(e.weight);
    return true;
}

// Whether instance `i` shades any of its mesh slots with an emissive material. compileInstances
// lays each instance's slots out after the previous one's, so they end where the next begin.
// The scan below skips the primitives of instances that cannot emit: a table over a scene
// without emissive surfaces costs O(instances x slots), not O(triangles).
bool instanceMayEmit(const RenderScene& scene, uint32_t i) {
    const uint32_t first = scene.instances[i].materialOffset;
    const uint32_t end =
        i + 1 < scene.instances.count ? scene.instances[i + 1].materialOffset : scene.instanceMaterials.count;
    for (uint32_t slot = first; slot < end; ++slot) {
        if (scene.materials[scene.instanceMaterials[slot]].isEmissive()) return true;
    }
    return false;
}

void addGeometryLights(const RenderScene& scene, EmitterTable& table, std::vector<float>& weights) {
    for (uint32_t i = 0; i < scene.instances.count; ++i) {
        if (!instanceMayEmit(scene, i)) continue;
        const RenderInstance& inst = scene.instances[i];
        const BlasRef& blas = scene.blases[inst.blas];
        for (uint32_t prim = 0; prim < blas.primitiveCount; ++prim) {
            const Material& m = emitterMaterial(scene, i, prim, blas.kind);
            if (!m.isEmissive()) continue;
            if (blas.kind == GeometryKind::Triangles) {
                const float weight = triangleLightWeight(worldTriangle(scene, i, prim), m);
                table.triangles += addEmitter(table, weights, {i, prim, weight, LightKind::Triangle});
                continue;
            }
            WorldSphere sphere;
            if (!worldSphere(scene, i, prim, sphere)) continue;  // an ellipsoid: BSDF sampling only
            table.spheres +=
                addEmitter(table, weights, {i, prim, sphereLightWeight(sphere, m), LightKind::Sphere});
        }
    }
}

}  // namespace

float sceneBoundingRadius(const RenderScene& scene) {
    if (scene.tlasNodes.count == 0 || scene.instances.count == 0) return 1.0f;
    const BvhNode& root = scene.tlasNodes[0];
    const float r = 0.5f * length(root.hi - root.lo);
    return std::isfinite(r) && r > 0.0f ? r : 1.0f;
}

EmitterTable buildEmitterTable(const RenderScene& scene, double environmentAverageLuminance) {
    EmitterTable table;
    std::vector<float> weights;
    addGeometryLights(scene, table, weights);
    const float radius = sceneBoundingRadius(scene);
    for (uint32_t i = 0; i < scene.punctualLights.count; ++i) {
        const float weight = punctualLightWeight(scene.punctualLights[i], radius);
        table.punctual += addEmitter(table, weights, {i, 0, weight, LightKind::Punctual});
    }
    const RenderEnvironment& env = scene.environment;
    const double envLuminance =
        env.texture >= 0 ? environmentAverageLuminance * env.intensity : double(luminance(env.color));
    const bool sampleable = env.texture < 0 || env.distWidth > 0;
    if (sampleable && envLuminance > 0.0) {
        double local = 0.0;
        for (float w : weights) local += w;
        double weight = 4.0 * kPi * double(radius) * radius * envLuminance;
        if (local > 0.0) {
            // Its share of the flux, kept within [1/4, 3/4] beside local lights (see header).
            const double share = std::clamp(weight / (weight + local), 0.25, 0.75);
            weight = share / (1.0 - share) * local;
        }
        if (addEmitter(table, weights, {0, 0, float(weight), LightKind::Environment})) {
            table.environmentWeight = float(weight);
        }
    }
    double total = 0.0;
    for (float w : weights) total += w;
    table.totalWeight = float(total);
    table.alias = buildAliasTable(weights);
    return table;
}

}  // namespace pt
