#include "render/lights/emitter_table.h"

#include "render/lights/emitter_sample.h"

namespace pt {

EmitterTable buildEmitterTable(const RenderScene& scene) {
    EmitterTable table;
    std::vector<float> weights;
    for (uint32_t i = 0; i < scene.instances.count; ++i) {
        const RenderInstance& inst = scene.instances[i];
        const BlasRef& blas = scene.blases[inst.blas];
        if (blas.kind != GeometryKind::Triangles) continue;  // emissive spheres: hit by BSDF rays only
        for (uint32_t prim = 0; prim < blas.primitiveCount; ++prim) {
            const Material& m = instanceMaterial(scene, inst, scene.triangleSlots[blas.primitiveOffset + prim]);
            if (!m.isEmissive()) continue;
            const float weight = worldTriangle(scene, i, prim).area * luminance(m.emittedRadiance());
            if (!(weight > 0.0f) || !std::isfinite(weight)) continue;
            table.emitters.push_back({i, prim, weight});
            weights.push_back(weight);
        }
    }
    // Sum in the order the device recomputes nothing from: only the total is shared.
    double total = 0.0;
    for (float w : weights) total += w;
    table.totalWeight = float(total);
    table.alias = buildAliasTable(weights);
    return table;
}

}  // namespace pt
