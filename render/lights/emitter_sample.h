#pragma once
// Emissive triangles as lights: world-space geometry, weight in the light table (area x
// luminance of the emitted radiance: power / pi of a one-sided Lambertian emitter), and a
// uniform point on one. Emission leaves the front face only (counter-clockwise winding in
// object space; a mirroring instance transform keeps the front face, as glTF specifies), as
// pbrt's one-sided area lights do.
#include "render/bvh/instance_space.h"
#include "render/kernel/render_scene.h"
#include "render/materials/alpha.h"
#include "render/materials/texture_sample.h"
#include "render/sampling/alias_table.h"
#include "render/sampling/warp.h"

namespace pt {

struct WorldTriangle {
    Vec3 p0, p1, p2;
    Vec3 frontNormal;  // unit
    float area;        // of the triangle as traced: the object-space one under objectToWorld
};

PT_HD const Material& instanceMaterial(const RenderScene& scene, const RenderInstance& instance,
                                       uint32_t slot) {
    return scene.materials[scene.instanceMaterials[instance.materialOffset + slot]];
}

// The material of primitive `primitive` of instance `instanceIndex`.
PT_HD const Material& emitterMaterial(const RenderScene& scene, uint32_t instanceIndex, uint32_t primitive,
                                      GeometryKind kind) {
    const RenderInstance& inst = scene.instances[instanceIndex];
    const BlasRef& blas = scene.blases[inst.blas];
    const uint32_t slot = kind == GeometryKind::Spheres
                              ? scene.sphereSlots[blas.primitiveOffset + primitive]
                              : scene.triangleSlots[blas.primitiveOffset + primitive];
    return instanceMaterial(scene, inst, slot);
}

PT_HD WorldTriangle worldTriangle(const RenderScene& scene, uint32_t instanceIndex, uint32_t primitive) {
    const RenderInstance& inst = scene.instances[instanceIndex];
    const BlasRef& blas = scene.blases[inst.blas];
    const TriangleIndices tri = scene.triangles[blas.primitiveOffset + primitive];
    WorldTriangle w;
    w.p0 = inst.objectToWorld.transformPoint(scene.positions[tri.v0]);
    w.p1 = inst.objectToWorld.transformPoint(scene.positions[tri.v1]);
    w.p2 = inst.objectToWorld.transformPoint(scene.positions[tri.v2]);
    // Edges from object space: the world vertices are rounded to the world's ulp (1/128 at 1e5,
    // a relative error of 1% on a unit edge), the edge vectors under the linear part are not.
    const Vec3 p0 = scene.positions[tri.v0];
    const Vec3 c = cross(inst.objectToWorld.transformVector(scene.positions[tri.v1] - p0),
                         inst.objectToWorld.transformVector(scene.positions[tri.v2] - p0));
    const float len = length(c);
    w.area = 0.5f * len;
    w.frontNormal = len > 0.0f ? c / len : Vec3{0.0f, 0.0f, 1.0f};
    // A mirroring transform reverses the world-space winding of the front face.
    if (inst.flipsWinding) w.frontNormal = -w.frontNormal;
    return w;
}

// Light-table weight of an emissive triangle; the integrator recomputes it on BSDF hits.
PT_HD float triangleLightWeight(const WorldTriangle& tri, const Material& m) {
    return tri.area * luminance(m.emittedRadiance());
}

template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 emittedRadiance(const RenderScene& scene, const Material& m, Vec2 uv) {
    Vec3 e = m.emittedRadiance();
    if (hasFeature<kF>(feature::kEmissiveTexture) && m.emissiveTexture.present())
        e *= sampleTexture(scene, m.emissiveTexture, uv, true).xyz();
    return e;
}

struct EmitterSample {
    Vec3 point;
    Vec3 pointError;  // per axis, for offsetRayOrigin()
    Vec3 normal;      // front normal of the emitter
    Vec3 radiance;    // leaving the front face, times the surface's alpha coverage there
    float area;       // world space
};

// A uniform point on triangle `primitive` of instance `instanceIndex`.
template <FeatureSet kF = kAllFeatures>
PT_HD bool sampleEmitterTriangle(const RenderScene& scene, uint32_t instanceIndex, uint32_t primitive,
                                 Vec2 uPoint, EmitterSample& out) {
    const WorldTriangle tri = worldTriangle(scene, instanceIndex, primitive);
    if (!(tri.area > 0.0f)) return false;
    const Vec2 b = squareToTriangle(uPoint);
    const RenderInstance& inst = scene.instances[instanceIndex];
    const BlasRef& blas = scene.blases[inst.blas];
    // Computed from object space, like hit points (surface_hit.h), so that it lies on the
    // triangle as traced and its error is known.
    const TriangleIndices t = scene.triangles[blas.primitiveOffset + primitive];
    const Vec3 p0 = scene.positions[t.v0], p1 = scene.positions[t.v1], p2 = scene.positions[t.v2];
    const SurfacePoint point = triangleSurfacePoint(inst, p0, p1, p2, {1.0f - b.x - b.y, b.x, b.y});
    out.point = point.position;
    out.pointError = point.error;
    out.normal = tri.frontNormal;
    out.area = tri.area;
    const Material& m = emitterMaterial(scene, instanceIndex, primitive, GeometryKind::Triangles);
    Vec2 uv{0.0f, 0.0f};
    if (hasFeature<kF>(feature::kEmissiveTexture | feature::kTransparency) && blas.hasUvs) {
        uv = scene.uvs[t.v0] * (1.0f - b.x - b.y) + scene.uvs[t.v1] * b.x + scene.uvs[t.v2] * b.y;
    }
    // Where the emitter is alpha-transparent, rays that hit it pass through (transparency.h);
    // NEE sees it with the same expected coverage.
    out.radiance = emittedRadiance<kF>(scene, m, uv) * surfaceCoverage<kF>(scene, m, uv);
    return true;
}

}  // namespace pt
