#pragma once
// Next-event estimation on emissive triangles: pick one in proportion to power, then a
// uniform point on it. Emission leaves the front face only (counter-clockwise winding, after
// the instance transform), as pbrt's one-sided area lights do.
#include "render/materials/texture_sample.h"
#include "render/sampling/alias_table.h"
#include "render/sampling/warp.h"
#include "render/scene/render_scene.h"

namespace pt {

struct WorldTriangle {
    Vec3 p0, p1, p2;
    Vec3 frontNormal;  // unit
    float area;
};

PT_HD const Material& instanceMaterial(const RenderScene& scene, const RenderInstance& instance,
                                       uint32_t slot) {
    return scene.materials[scene.instanceMaterials[instance.materialOffset + slot]];
}

PT_HD WorldTriangle worldTriangle(const RenderScene& scene, uint32_t instanceIndex, uint32_t primitive) {
    const RenderInstance& inst = scene.instances[instanceIndex];
    const BlasRef& blas = scene.blases[inst.blas];
    const TriangleIndices tri = scene.triangles[blas.primitiveOffset + primitive];
    WorldTriangle w;
    w.p0 = inst.objectToWorld.transformPoint(scene.positions[tri.v0]);
    w.p1 = inst.objectToWorld.transformPoint(scene.positions[tri.v1]);
    w.p2 = inst.objectToWorld.transformPoint(scene.positions[tri.v2]);
    const Vec3 c = cross(w.p1 - w.p0, w.p2 - w.p0);
    const float len = length(c);
    w.area = 0.5f * len;
    w.frontNormal = len > 0.0f ? c / len : Vec3{0.0f, 0.0f, 1.0f};
    if (inst.flipsWinding) w.frontNormal = -w.frontNormal;
    return w;
}

// Probability that NEE picks this emitter: the weight it was given at build time over the
// total, recomputed from the same inputs so that BSDF-sampled hits get the same number.
PT_HD float emitterPickProbability(const RenderScene& scene, float worldArea, const Material& m) {
    if (scene.emitterTotalWeight <= 0.0f) return 0.0f;
    return worldArea * luminance(m.emittedRadiance()) / scene.emitterTotalWeight;
}

struct EmitterSample {
    Vec3 point;
    Vec3 normal;     // front normal of the emitter
    Vec3 radiance;   // leaving the front face
    uint32_t uvValid;
    float pdfArea;   // pick probability / area
};

PT_HD Vec3 emittedRadiance(const RenderScene& scene, const Material& m, Vec2 uv) {
    Vec3 e = m.emittedRadiance();
    if (m.emissiveTexture.present()) e *= sampleTexture(scene, m.emissiveTexture, uv, true).xyz();
    return e;
}

PT_HD bool sampleEmitter(const RenderScene& scene, float uPick, Vec2 uPoint, EmitterSample& out) {
    if (scene.emitterAlias.count == 0) return false;
    const Emitter& e = scene.emitters[sampleAliasTable(scene.emitterAlias, uPick)];
    const WorldTriangle tri = worldTriangle(scene, e.instance, e.primitive);
    if (tri.area <= 0.0f) return false;
    const Vec2 b = squareToTriangle(uPoint);
    out.point = tri.p0 * (1.0f - b.x - b.y) + tri.p1 * b.x + tri.p2 * b.y;
    out.normal = tri.frontNormal;
    const RenderInstance& inst = scene.instances[e.instance];
    const BlasRef& blas = scene.blases[inst.blas];
    const Material& m = instanceMaterial(scene, inst, scene.triangleSlots[blas.primitiveOffset + e.primitive]);
    Vec2 uv{0.0f, 0.0f};
    if (blas.hasUvs) {
        const TriangleIndices t = scene.triangles[blas.primitiveOffset + e.primitive];
        uv = scene.uvs[t.v0] * (1.0f - b.x - b.y) + scene.uvs[t.v1] * b.x + scene.uvs[t.v2] * b.y;
    }
    out.radiance = emittedRadiance(scene, m, uv);
    out.pdfArea = emitterPickProbability(scene, tri.area, m) / tri.area;
    return out.pdfArea > 0.0f;
}

}  // namespace pt
