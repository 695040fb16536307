#pragma once
// A dielectric interface with GGX roughness that reflects and refracts (KHR_materials_
// transmission + KHR_materials_ior): Walter et al., "Microfacet Models for Refraction through
// Rough Surfaces" (EGSR 2007), with the exact unpolarised Fresnel term, total internal
// reflection, height-correlated masking and visible-normal sampling (as in pbrt-v4's
// DielectricBxDF). Works from both sides: wo.z < 0 is inside the object.
//
// Reflection is scaled by reflectTint (KHR_materials_specular's factor x color, clamped to 1);
// refraction keeps 1 - F, so total internal reflection stays physical, and is tinted by
// baseColor. Refracted radiance is scaled by 1 / eta^2 (Veach 1997, 5.2); the integrator's
// etaScale undoes it for Russian roulette. A white interface is lossless when smooth and loses
// only the single-scattering energy of GGX when rough: every sample weight (times eta^2 when
// refracted) is at most 1.
//
// The interface is treated as smooth (a delta lobe, exact) when alpha < kGgxSmoothAlpha, or when
// the indices match to within kIndexMatchedEta: the rough lobe then narrows to a spike that float
// cannot resolve, and at eta == 1 it is a pass-through.
//
// The rough functions take the GGX alpha apart from the interface as well: a GgxAlpha2 there is
// KHR_materials_anisotropy's stretched roughness (ggx.h); `alpha` of the interface then only
// decides smoothness. They also take the Fresnel term as a callable of (cos, eta): the exact
// term (a float), or one reflectance per channel (a Vec3: KHR_materials_iridescence's film on
// glass, bsdf.h); refraction keeps 1 - F per channel, and the choice between the two goes by the
// largest channel of each.
#include <type_traits>

#include "render/materials/fresnel.h"
#include "render/materials/ggx.h"
#include "render/materials/lobe_sample.h"

namespace pt {

constexpr float kIndexMatchedEta = 1e-3f;

struct DielectricInterface {
    float alpha;        // GGX
    float eta;          // index inside / index outside (the material's ior)
    Vec3 reflectTint;   // in [0, 1]
    Vec3 transmitTint;  // baseColor
};

PT_HD bool dielectricIsSmooth(const DielectricInterface& d) {
    return ggxIsSmooth(d.alpha) || !(fabsf(d.eta - 1.0f) >= kIndexMatchedEta);
}

// eta_transmitted / eta_incident for light arriving from wo's side.
PT_HD float relativeEta(const DielectricInterface& d, Vec3 wo) { return wo.z > 0.0f ? d.eta : 1.0f / d.eta; }

// Probability of reflecting at a (micro)surface of Fresnel reflectance `fresnel`: the share of
// reflection in the untinted-refraction sum, so that reflection weights stay <= 1.
PT_HD float reflectProbability(const DielectricInterface& d, float fresnel) {
    const float r = fresnel * maxComponent(d.reflectTint), t = 1.0f - fresnel;
    return r + t > 0.0f ? r / (r + t) : 0.0f;
}
PT_HD float refractProbability(const DielectricInterface& d, float fresnel) {
    const float r = fresnel * maxComponent(d.reflectTint), t = 1.0f - fresnel;
    return r + t > 0.0f ? t / (r + t) : 0.0f;
}
PT_HD float reflectProbability(const DielectricInterface& d, Vec3 fresnel) {
    const float r = maxComponent(fresnel * d.reflectTint), t = maxComponent(Vec3(1.0f) - fresnel);
    return r + t > 0.0f ? r / (r + t) : 0.0f;
}
PT_HD float refractProbability(const DielectricInterface& d, Vec3 fresnel) {
    const float r = maxComponent(fresnel * d.reflectTint), t = maxComponent(Vec3(1.0f) - fresnel);
    return r + t > 0.0f ? t / (r + t) : 0.0f;
}
PT_HD float oneMinus(float fresnel) { return 1.0f - fresnel; }
PT_HD Vec3 oneMinus(Vec3 fresnel) { return Vec3(1.0f) - fresnel; }

// The exact unpolarised Fresnel term of the interface.
struct ExactDielectricFresnel {
    PT_HD float operator()(float cosTheta, float etap) const { return fresnelDielectric(cosTheta, etap); }
};

// The generalised half vector of (wo, wi) facing +z, with its cosines; false for a
// configuration no microfacet produces.
PT_HD bool dielectricHalfVector(const DielectricInterface& d, Vec3 wo, Vec3 wi, Vec3& m, float& etap) {
    if (wo.z == 0.0f || wi.z == 0.0f) return false;
    const bool reflected = wo.z * wi.z > 0.0f;
    etap = relativeEta(d, wo);
    const Vec3 h = reflected ? wo + wi : wo + wi * etap;
    const float len2 = lengthSquared(h);
    if (!(len2 > 0.0f)) return false;
    m = h * (1.0f / sqrtf(len2));
    if (m.z < 0.0f) m = -m;
    // Microfacets seen from behind by either direction contribute nothing.
    return dot(wo, m) * wo.z > 0.0f && dot(wi, m) * wi.z > 0.0f;
}

// f * |cos(wi)| of the rough interface (zero when smooth: its lobes are delta).
template <class Alpha, class Fresnel = ExactDielectricFresnel>
PT_HD Vec3 evalRoughDielectric(const DielectricInterface& d, Vec3 wo, Vec3 wi, Alpha alpha,
                               const Fresnel& fresnelOf = {}) {
    Vec3 m;
    float etap;
    if (!dielectricHalfVector(d, wo, wi, m, etap)) return Vec3(0.0f);
    const float cosO = dot(wo, m), cosI = dot(wi, m);
    const auto fresnel = fresnelOf(fabsf(cosO), etap);
    const float muO = fabsf(wo.z), muI = fabsf(wi.z);
    const float maskSum = muI * ggxMaskingTerm(wo, alpha) + muO * ggxMaskingTerm(wi, alpha);
    if (!(maskSum > 0.0f)) return Vec3(0.0f);
    const float D = ggxD(m, alpha);
    if (wo.z * wi.z > 0.0f) {
        return d.reflectTint * (fresnel * D * muI / (2.0f * maskSum));  // F D G2 / (4 cos_o)
    }
    const float root = cosI + cosO / etap;
    const float denom = root * root;
    if (!(denom > 0.0f)) return Vec3(0.0f);
    // (1 - F) D G2 |i.m| |o.m| / (|cos_o| (i.m + o.m / eta)^2) / eta^2, with G2 / cos_o folded in.
    const auto ft = oneMinus(fresnel) * D * 2.0f * muI * fabsf(cosI * cosO) / (maskSum * denom);
    return d.transmitTint * (ft / (etap * etap));
}
PT_HD Vec3 evalRoughDielectric(const DielectricInterface& d, Vec3 wo, Vec3 wi) {
    return evalRoughDielectric(d, wo, wi, d.alpha);
}

// Solid-angle density with which sampleRoughDielectric picks wi.
template <class Alpha, class Fresnel = ExactDielectricFresnel>
PT_HD float pdfRoughDielectric(const DielectricInterface& d, Vec3 wo, Vec3 wi, Alpha alpha,
                               const Fresnel& fresnelOf = {}) {
    Vec3 m;
    float etap;
    if (!dielectricHalfVector(d, wo, wi, m, etap)) return 0.0f;
    const float cosO = dot(wo, m), cosI = dot(wi, m);
    const auto fresnel = fresnelOf(fabsf(cosO), etap);
    const float muO = fabsf(wo.z);
    const float D = ggxD(m, alpha);
    const float visibleDenom = muO + ggxMaskingTerm(wo, alpha);  // D_wo(m) = 2 |o.m| D / this
    if (wo.z * wi.z > 0.0f) {
        return reflectProbability(d, fresnel) * D / (2.0f * visibleDenom);  // D_wo / (4 |o.m|)
    }
    const float root = cosI + cosO / etap;
    const float denom = root * root;
    if (!(denom > 0.0f)) return 0.0f;
    return refractProbability(d, fresnel) * 2.0f * fabsf(cosO) * D / visibleDenom * fabsf(cosI) / denom;
}
PT_HD float pdfRoughDielectric(const DielectricInterface& d, Vec3 wo, Vec3 wi) {
    return pdfRoughDielectric(d, wo, wi, d.alpha);
}

// Picks a visible microfacet with uDir, then reflection or refraction with uChoice.
template <class Alpha, class Fresnel = ExactDielectricFresnel>
PT_HD LobeSample sampleRoughDielectric(const DielectricInterface& d, Vec3 wo, float uChoice, Vec2 uDir,
                                       Alpha alpha, const Fresnel& fresnelOf = {}) {
    LobeSample s{};
    if (wo.z == 0.0f) return s;
    const bool inside = wo.z < 0.0f;
    Vec3 m = sampleGgxVisibleNormal(inside ? -wo : wo, alpha, uDir);
    if (inside) m = -m;  // the microfacet normal on wo's side
    const float cosO = dot(wo, m);
    if (!(cosO > 0.0f)) return s;
    const float etap = relativeEta(d, wo);
    const auto fresnel = fresnelOf(cosO, etap);
    if (uChoice < reflectProbability(d, fresnel)) {
        s.wi = reflect(wo, m);
        if (!(s.wi.z * wo.z > 0.0f)) return s;
    } else {
        Vec3 wt;
        if (!refractDirection(wo, m, etap, wt)) return s;
        s.wi = normalize(wt);
        if (!(s.wi.z * wo.z < 0.0f)) return s;
        s.transmitted = true;
    }
    s.pdf = pdfRoughDielectric(d, wo, s.wi, alpha, fresnelOf);
    if (!(s.pdf > 0.0f)) return s;
    s.weight = evalRoughDielectric(d, wo, s.wi, alpha, fresnelOf) / s.pdf;
    s.valid = true;
    return s;
}
PT_HD LobeSample sampleRoughDielectric(const DielectricInterface& d, Vec3 wo, float uChoice, Vec2 uDir) {
    return sampleRoughDielectric(d, wo, uChoice, uDir, d.alpha);
}

// The smooth interface: specular reflection or refraction, chosen with uChoice.
template <class Fresnel = ExactDielectricFresnel>
PT_HD LobeSample sampleSmoothDielectric(const DielectricInterface& d, Vec3 wo, float uChoice,
                                        const Fresnel& fresnelOf = {}) {
    LobeSample s{};
    if (wo.z == 0.0f) return s;
    const float etap = relativeEta(d, wo);
    const auto fresnel = fresnelOf(fabsf(wo.z), etap);
    constexpr bool kScalar = std::is_same_v<std::remove_const_t<decltype(fresnel)>, float>;
    float r, t;
    if constexpr (kScalar) {
        r = fresnel * maxComponent(d.reflectTint), t = 1.0f - fresnel;
    } else {
        r = maxComponent(fresnel * d.reflectTint), t = maxComponent(Vec3(1.0f) - fresnel);
    }
    if (!(r + t > 0.0f)) return s;
    s.delta = true;
    if (uChoice * (r + t) < r) {
        s.wi = {-wo.x, -wo.y, wo.z};
        s.weight = d.reflectTint * (fresnel * (r + t) / r);
        s.valid = true;
        return s;
    }
    Vec3 wt;
    const Vec3 n{0.0f, 0.0f, wo.z > 0.0f ? 1.0f : -1.0f};
    if (!refractDirection(wo, n, etap, wt)) return s;  // unreachable: t == 0 under TIR
    s.wi = normalize(wt);
    s.weight = d.transmitTint * ((r + t) / (etap * etap));
    if constexpr (!kScalar) s.weight *= oneMinus(fresnel) / t;  // each channel's own share
    s.transmitted = true;
    s.valid = true;
    return s;
}

}  // namespace pt
