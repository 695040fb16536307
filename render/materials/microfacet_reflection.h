#pragma once
// GGX microfacet reflection with Schlick's Fresnel, f = F(wo.h) D(h) G2 / (4 cos_o cos_i): the
// glTF specular_brdf of metals and of the dielectric specular layer, and (F0 = F90 = 1) the
// clearcoat layer. Front side only: wo.z > 0 and wi.z > 0 in the shading frame. Sampled by
// visible normals, so the sample weight is F G2 / G1(wo) <= F.
#include "render/materials/fresnel.h"
#include "render/materials/ggx.h"
#include "render/materials/lobe_sample.h"

namespace pt {

// f * cos(wi).
PT_HD Vec3 evalGgxReflection(Vec3 wo, Vec3 wi, float alpha, Vec3 f0, Vec3 f90) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return Vec3(0.0f);
    const Vec3 sum = wo + wi;
    const float len2 = lengthSquared(sum);
    if (!(len2 > 0.0f)) return Vec3(0.0f);
    const Vec3 h = sum * (1.0f / sqrtf(len2));
    const float denom = wi.z * ggxMaskingTerm(wo, alpha) + wo.z * ggxMaskingTerm(wi, alpha);
    if (!(denom > 0.0f)) return Vec3(0.0f);
    return fresnelSchlick(f0, f90, dot(wo, h)) * (ggxD(h, alpha) * wi.z / (2.0f * denom));
}

// Solid-angle density of sampleGgxReflection: D_wo(h) / (4 wo.h) = D(h) G1(wo) / (4 cos_o).
PT_HD float pdfGgxReflection(Vec3 wo, Vec3 wi, float alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const Vec3 sum = wo + wi;
    const float len2 = lengthSquared(sum);
    if (!(len2 > 0.0f)) return 0.0f;
    const Vec3 h = sum * (1.0f / sqrtf(len2));
    return ggxD(h, alpha) / (2.0f * (wo.z + ggxMaskingTerm(wo, alpha)));
}

PT_HD LobeSample sampleGgxReflection(Vec3 wo, float alpha, Vec3 f0, Vec3 f90, Vec2 u) {
    LobeSample s{};
    if (wo.z <= 0.0f) return s;
    const Vec3 m = sampleGgxVisibleNormal(wo, alpha, u);
    s.wi = reflect(wo, m);
    if (s.wi.z <= 0.0f) return s;  // shadowed below the horizon: no sample
    s.pdf = pdfGgxReflection(wo, s.wi, alpha);
    if (!(s.pdf > 0.0f)) return s;
    s.weight = evalGgxReflection(wo, s.wi, alpha, f0, f90) / s.pdf;
    s.valid = true;
    return s;
}

// The perfectly smooth limit: a mirror with weight F(cos_o).
PT_HD LobeSample sampleSmoothReflection(Vec3 wo, Vec3 f0, Vec3 f90) {
    LobeSample s{};
    if (wo.z <= 0.0f) return s;
    s.wi = {-wo.x, -wo.y, wo.z};
    s.weight = fresnelSchlick(f0, f90, wo.z);
    s.delta = true;
    s.valid = true;
    return s;
}

}  // namespace pt
