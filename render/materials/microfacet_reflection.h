#pragma once
// GGX microfacet reflection, f = F(wo.h) D(h) G2 / (4 cos_o cos_i): the glTF specular_brdf of
// metals and of the dielectric specular layer, and (F0 = F90 = 1) the clearcoat layer. Front
// side only: wo.z > 0 and wi.z > 0 in the shading frame. Sampled by visible normals, so the
// sample weight is F G2 / G1(wo) <= F.
//
// `alpha` is a float (isotropic) or a GgxAlpha2 (KHR_materials_anisotropy); the Fresnel term is
// Schlick's with F0 and F90, or any callable of cos(wo.h) (the thin film of
// KHR_materials_iridescence, iridescence.h).
#include "render/materials/fresnel.h"
#include "render/materials/ggx.h"
#include "render/materials/lobe_sample.h"

namespace pt {

// Schlick's approximation as a Fresnel term of the microfacet's cosine.
struct SchlickFresnel {
    Vec3 f0, f90;
    PT_HD Vec3 operator()(float cosTheta) const { return fresnelSchlick(f0, f90, cosTheta); }
};

// f * cos(wi).
template <class Alpha, class Fresnel>
PT_HD Vec3 evalGgxReflection(Vec3 wo, Vec3 wi, Alpha alpha, const Fresnel& fresnel) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return Vec3(0.0f);
    const Vec3 sum = wo + wi;
    const float len2 = lengthSquared(sum);
    if (!(len2 > 0.0f)) return Vec3(0.0f);
    const Vec3 h = sum * (1.0f / sqrtf(len2));
    const float denom = wi.z * ggxMaskingTerm(wo, alpha) + wo.z * ggxMaskingTerm(wi, alpha);
    if (!(denom > 0.0f)) return Vec3(0.0f);
    return fresnel(dot(wo, h)) * (ggxD(h, alpha) * wi.z / (2.0f * denom));
}
template <class Alpha>
PT_HD Vec3 evalGgxReflection(Vec3 wo, Vec3 wi, Alpha alpha, Vec3 f0, Vec3 f90) {
    return evalGgxReflection(wo, wi, alpha, SchlickFresnel{f0, f90});
}

// Solid-angle density of sampleGgxReflection: D_wo(h) / (4 wo.h) = D(h) G1(wo) / (4 cos_o).
template <class Alpha>
PT_HD float pdfGgxReflection(Vec3 wo, Vec3 wi, Alpha alpha) {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const Vec3 sum = wo + wi;
    const float len2 = lengthSquared(sum);
    if (!(len2 > 0.0f)) return 0.0f;
    const Vec3 h = sum * (1.0f / sqrtf(len2));
    return ggxD(h, alpha) / (2.0f * (wo.z + ggxMaskingTerm(wo, alpha)));
}

template <class Alpha, class Fresnel>
PT_HD LobeSample sampleGgxReflection(Vec3 wo, Alpha alpha, const Fresnel& fresnel, Vec2 u) {
    LobeSample s{};
    if (wo.z <= 0.0f) return s;
    const Vec3 m = sampleGgxVisibleNormal(wo, alpha, u);
    s.wi = reflect(wo, m);
    if (s.wi.z <= 0.0f) return s;  // shadowed below the horizon: no sample
    s.pdf = pdfGgxReflection(wo, s.wi, alpha);
    if (!(s.pdf > 0.0f)) return s;
    s.weight = evalGgxReflection(wo, s.wi, alpha, fresnel) / s.pdf;
    s.valid = true;
    return s;
}
template <class Alpha>
PT_HD LobeSample sampleGgxReflection(Vec3 wo, Alpha alpha, Vec3 f0, Vec3 f90, Vec2 u) {
    return sampleGgxReflection(wo, alpha, SchlickFresnel{f0, f90}, u);
}

// The perfectly smooth limit: a mirror with weight F(cos_o).
template <class Fresnel>
PT_HD LobeSample sampleSmoothReflection(Vec3 wo, const Fresnel& fresnel) {
    LobeSample s{};
    if (wo.z <= 0.0f) return s;
    s.wi = {-wo.x, -wo.y, wo.z};
    s.weight = fresnel(wo.z);
    s.delta = true;
    s.valid = true;
    return s;
}
PT_HD LobeSample sampleSmoothReflection(Vec3 wo, Vec3 f0, Vec3 f90) {
    return sampleSmoothReflection(wo, SchlickFresnel{f0, f90});
}

}  // namespace pt
