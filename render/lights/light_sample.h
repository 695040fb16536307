#pragma once
// Next-event estimation over every kind of light: pick one from the alias table in
// proportion to its weight (emitter_table.h), then a direction towards it from the shading
// point. Area lights and the environment return a solid-angle density for MIS; punctual
// lights are delta lights (no MIS: BSDF sampling can never hit them).
//
// The *_LightPdf functions give the density NEE would have had for a direction that BSDF
// sampling found, computed from the same weights, so both strategies agree.
#include "render/lights/emitter_sample.h"
#include "render/lights/environment_sampling.h"
#include "render/lights/punctual_light.h"
#include "render/lights/sphere_light.h"

namespace pt {

struct LightSample {
    Vec3 wi;          // unit, from the shading point towards the light
    Vec3 radiance;    // arriving along wi: Le (area, environment), I/d^2 x falloff, or E (directional)
    Vec3 point;       // on the light, for the shadow ray (finite lights)
    Vec3 pointError;  // per axis, for offsetRayOrigin() (area lights); zero for the others
    Vec3 normal;      // front normal at `point` (area lights); zero for punctual lights
    float distance;   // to `point`; kInf for directional lights and the environment
    float pdf;        // solid-angle density x pick probability; delta lights: the pick probability
    bool delta;
};

PT_HD float lightPickProbability(const RenderScene& scene, float weight) {
    return scene.emitterTotalWeight > 0.0f ? weight / scene.emitterTotalWeight : 0.0f;
}

template <FeatureSet kF = kAllFeatures>
PT_HD bool sampleTriangleLight(const RenderScene& scene, const Emitter& e, Vec3 ref, Vec2 u,
                               LightSample& out) {
    EmitterSample s;
    if (!sampleEmitterTriangle<kF>(scene, e.instance, e.primitive, u, s)) return false;
    const Vec3 toLight = s.point - ref;
    const float distance2 = lengthSquared(toLight);
    if (!(distance2 > 0.0f)) return false;
    const float distance = sqrtf(distance2);
    out.wi = toLight / distance;
    const float cosLight = -dot(s.normal, out.wi);
    if (cosLight <= 0.0f) return false;  // the light's back faces us
    out.radiance = s.radiance;
    out.point = s.point;
    out.pointError = s.pointError;
    out.normal = s.normal;
    out.distance = distance;
    out.pdf = lightPickProbability(scene, e.weight) * distance2 / (s.area * cosLight);
    out.delta = false;
    return isFinite(out.pdf) && out.pdf > 0.0f;
}

template <FeatureSet kF = kAllFeatures>
PT_HD bool sampleSphereLight(const RenderScene& scene, const Emitter& e, Vec3 ref, Vec2 u, LightSample& out) {
    WorldSphere sphere;
    if (!worldSphere(scene, e.instance, e.primitive, sphere)) return false;
    SphereConeSample s;
    if (!sampleSphereCone(sphere, ref, u, s)) return false;
    out.wi = s.wi;
    out.point = s.point;
    const RenderInstance& inst = scene.instances[e.instance];
    const Vec4 object = scene.spheres[scene.blases[inst.blas].primitiveOffset + e.primitive];
    out.pointError = spherePointError(inst, object);
    out.normal = s.normal;
    out.distance = s.distance;
    out.radiance = sphereEmittedRadiance<kF>(scene, e.instance, e.primitive, s.point);
    out.pdf = lightPickProbability(scene, e.weight) * s.pdf;
    out.delta = false;
    return isFinite(out.pdf) && out.pdf > 0.0f;
}

template <FeatureSet kF = kAllFeatures>
PT_HD bool sampleEnvironmentLight(const RenderScene& scene, const Emitter& e, Vec2 u, LightSample& out) {
    float pdf;
    if (!sampleEnvironmentDirection<kF>(scene, u, out.wi, pdf)) return false;
    out.radiance = environmentRadiance<kF>(scene, out.wi);
    out.point = Vec3(0.0f);
    out.pointError = Vec3(0.0f);
    out.normal = Vec3(0.0f);
    out.distance = kInf;
    out.pdf = lightPickProbability(scene, e.weight) * pdf;
    out.delta = false;
    return isFinite(out.pdf) && out.pdf > 0.0f;
}

// One light sample for shading point `ref`: `uPick` chooses the light, `uPoint` the point.
// Kinds of light the kernel's feature set kF leaves out are never in the scene's table.
template <FeatureSet kF = kAllFeatures>
PT_HD bool sampleLight(const RenderScene& scene, Vec3 ref, float uPick, Vec2 uPoint, LightSample& out) {
    if (scene.emitterAlias.count == 0) return false;
    const Emitter& e = scene.emitters[sampleAliasTable(scene.emitterAlias, uPick)];
    switch (e.kind) {
        case LightKind::Triangle: return sampleTriangleLight<kF>(scene, e, ref, uPoint, out);
        case LightKind::Sphere:
            if (!hasFeature<kF>(feature::kSphereLights)) return false;
            return sampleSphereLight<kF>(scene, e, ref, uPoint, out);
        case LightKind::Environment:
            if (!hasFeature<kF>(feature::kConstantEnvironment | feature::kImageEnvironment)) return false;
            return sampleEnvironmentLight<kF>(scene, e, uPoint, out);
        case LightKind::Punctual: {
            if (!hasFeature<kF>(feature::kPunctualLights)) return false;
            PunctualSample s;
            if (!samplePunctualLight(scene.punctualLights[e.instance], ref, s)) return false;
            out.wi = s.wi;
            out.radiance = s.radiance;
            out.point = s.point;
            out.pointError = Vec3(0.0f);
            out.normal = Vec3(0.0f);
            out.distance = s.distance;
            out.pdf = lightPickProbability(scene, e.weight);
            out.delta = true;
            return out.pdf > 0.0f;
        }
    }
    return false;
}

// NEE's density for a BSDF-sampled ray from `ref` that hit the front of emissive triangle
// `primitive` of instance `instance` at `point`, whose front normal is `normal`.
PT_HD float triangleLightPdf(const RenderScene& scene, uint32_t instance, uint32_t primitive, Vec3 ref,
                             Vec3 point, Vec3 normal) {
    const WorldTriangle tri = worldTriangle(scene, instance, primitive);
    const Material& m = emitterMaterial(scene, instance, primitive, GeometryKind::Triangles);
    const float pick = lightPickProbability(scene, triangleLightWeight(tri, m));
    if (!(pick > 0.0f) || !(tri.area > 0.0f)) return 0.0f;
    const Vec3 toLight = point - ref;
    const float distance2 = lengthSquared(toLight);
    const float cosLight = fabsf(dot(normal, toLight)) / sqrtf(distance2);
    return cosLight > 0.0f ? pick * distance2 / (tri.area * cosLight) : 0.0f;
}

// The same for an emissive sphere; 0 for spheres NEE does not sample (non-uniform scale).
PT_HD float sphereLightPdf(const RenderScene& scene, uint32_t instance, uint32_t primitive, Vec3 ref) {
    WorldSphere sphere;
    if (!worldSphere(scene, instance, primitive, sphere)) return 0.0f;
    const Material& m = emitterMaterial(scene, instance, primitive, GeometryKind::Spheres);
    const float pick = lightPickProbability(scene, sphereLightWeight(sphere, m));
    return pick > 0.0f ? pick * sphereConePdf(sphere, ref) : 0.0f;
}

// The same for a ray that left the scene in `direction` (unit).
template <FeatureSet kF = kAllFeatures>
PT_HD float environmentLightPdf(const RenderScene& scene, Vec3 direction) {
    if (!hasFeature<kF>(feature::kConstantEnvironment | feature::kImageEnvironment)) return 0.0f;
    const float pick = lightPickProbability(scene, scene.environment.lightWeight);
    return pick > 0.0f ? pick * environmentDirectionPdf<kF>(scene, direction) : 0.0f;
}

}  // namespace pt
