#pragma once
// The surface BSDF of a Material at one shading point: the glTF 2.0 metallic-roughness model
// (Appendix B) with KHR_materials_ior, _specular, _transmission and _clearcoat, in the shading
// frame (local z is the shading normal, pointing to the front side). A mixture of lobes:
//
//   coat      w = clearcoat Fresnel(N.V)            white GGX, clearcoat.h (front only)
//   and, scaled by 1 - w:
//   sheen     c = sheenColor, normalised            Charlie fibres, sheen.h (front only)
//   and, scaled by 1 - max(c) E_sheen(N.V) (front only):
//   specular  metallic + (1-m)(1-t) layer           GGX reflection, Schlick F0/F90,
//                                                   microfacet_reflection.h (front only)
//   diffuse   (1-m)(1-t)(1-d)                       Lambert under the specular layer,
//                                                   layered_diffuse.h (front only)
//   diffuse   (1-m)(1-t) d                          KHR_materials_diffuse_transmission: Lambert
//   transm.                                         into the other hemisphere, tinted, through
//                                                   the specular layer at wo (front only)
//   glass     (1-m) t                               rough dielectric BSDF, rough_dielectric.h
//
// Metal and the dielectric specular layer share one GGX lobe: Schlick's F is linear in F0 and
// F90, so their mix is one Schlick term. Lobes below kGgxSmoothAlpha are delta lobes. sampleBsdf
// picks a lobe with probability proportional to its estimated albedo at wo; for a non-delta
// direction it returns the weight and pdf of the whole non-delta mixture (one-sample MIS over
// the lobes), so pdfBsdf() is exactly the density of the directions it produces.
//
// kF, a scene feature set (feature_set.h), leaves out the coat without feature::kClearcoat
// and the glass lobe without feature::kTransmission: kernels specialised on a scene with
// neither carry no code for them, the diffuse transmission lobe without
// feature::kDiffuseTransmission and the sheen without feature::kSheen. The parameters must then
// have clearcoat 0, transmission 0, diffuse transmission 0 and a black sheen.
//
// KHR_materials_anisotropy stretches the GGX alpha of the specular and glass lobes along the
// frame's x (feature::kAnisotropy); KHR_materials_iridescence puts a thin film (iridescence.h)
// on the Fresnel terms of the specular and glass lobes (feature::kIridescence), and the diffuse
// base under it gets what the film lets through at wo.
#include "render/kernel/feature_set.h"
#include "render/materials/clearcoat.h"
#include "render/materials/iridescence.h"
#include "render/materials/layered_diffuse.h"
#include "render/materials/rough_dielectric.h"
#include "render/materials/sheen.h"
#include "render/math/frame.h"
#include "render/sampling/warp.h"

namespace pt {

// Resolved glTF parameters of one shading point (material_eval.h fills it from a Material).
// The first four members keep their historical order for aggregate initialisation.
struct BsdfParams {
    Vec3 baseColor;
    float metallic;
    float transmission;
    float ior;               // interior / exterior, >= 1
    float roughness = 0.5f;  // GGX alpha = roughness^2
    float specular = 1.0f;   // KHR_materials_specular factor
    Vec3 specularColor{1.0f, 1.0f, 1.0f};
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.0f;
    float diffuseTransmission = 0.0f;  // KHR_materials_diffuse_transmission factor
    Vec3 diffuseTransmissionColor{1.0f, 1.0f, 1.0f};
    Vec3 sheenColor{0.0f, 0.0f, 0.0f};  // KHR_materials_sheen; black: no sheen
    float sheenRoughness = 0.0f;
    // KHR_materials_anisotropy: alpha along the shading frame's x is mix(alpha, 1, strength^2)
    // (the integrator turns the frame to the direction, anisotropy_frame.h).
    float anisotropy = 0.0f;
    Vec2 anisotropyDirection{1.0f, 0.0f};  // in tangent space, unit
    float iridescence = 0.0f;              // KHR_materials_iridescence: the film's weight
    float iridescenceIor = 1.3f;
    float iridescenceThickness = 400.0f;  // nanometres
    // The share of `transmission` that is subsurface scattering (material_eval.h): it enters a
    // medium that gives it its colour, so the surface does not tint it by the base colour.
    float untintedTransmission = 0.0f;
};

struct BsdfSample {
    Vec3 wi;      // world space, unit
    Vec3 weight;  // f * |cos| / pdf
    float pdf;    // solid-angle density; meaningless when `delta`
    bool delta;   // from a specular lobe: no light sampling, no MIS
    bool transmitted;
    bool refracted;  // through the dielectric interface (radiance scales by eta^2), not diffusely
};

// Whether the BSDF can refract: the integrator keeps the geometric sidedness of such surfaces
// (inside versus outside) instead of shading both sides as fronts.
PT_HD bool isTransmissive(const BsdfParams& p) {
    return (1.0f - clampf(p.metallic, 0.0f, 1.0f)) * clampf(p.transmission, 0.0f, 1.0f) > 0.0f;
}

namespace bsdf_detail {

enum Lobe : int {
    kCoat = 0,
    kSpecular = 1,
    kDiffuse = 2,
    kGlass = 3,
    kDiffuseTransmission = 4,
    kSheen = 5,
    kLobeCount = 6
};

// The lobes code compiled for kF walks: the rare lobes (feature::kRareLobes) come last, and
// loops stop before those kF leaves out.
template <FeatureSet kF>
constexpr int lobesFor() {
    return hasFeature<kF>(feature::kSheen)                 ? kLobeCount
           : hasFeature<kF>(feature::kDiffuseTransmission) ? kSheen
                                                           : kDiffuseTransmission;
}

// The rare lobes' weights and parameters: members of Lobes only in code compiled for them.
template <bool kRare>
struct RareLobeWeights {};
template <>
struct RareLobeWeights<true> {
    Vec3 diffuseTransmitted;  // its albedo: color * mix weight * the layer's transmittance at wo
    Vec3 sheen;               // sheenColor * mix weight / max(1, E_sheen(mu_o))
    float sheenAlpha;
    float alphaT;           // GGX alpha along the anisotropy direction (x); `alpha` is along y
    FilmedSpecular filmed;  // the thin film on the specular and glass lobes
};

// Everything that depends on the parameters and wo only, in the shading frame. It holds only
// what kF can use: sampleBsdf indexes its probabilities with the lobe it picked, which keeps
// the whole of it in local memory, so every member more is stack traffic (the rare lobes'
// seven floats cost the lean shading kernel 24 bytes of stack, 2 registers and 1.7% before).
template <FeatureSet kF>
struct Lobes : RareLobeWeights<(kF & feature::kRareLobes) != 0u> {
    float coat;  // mix weight of the coat (0 from the back)
    float coatAlpha;
    Vec3 specF0, specF90;  // the shared GGX reflection lobe, mix weights folded in
    float alpha;
    DiffuseLayer layer;  // the dielectric specular layer over the diffuse base
    Vec3 diffuse;        // baseColor * mix weight * (1 - E(mu_o)) / (1 - E_avg)
    float glass;         // mix weight of the dielectric interface
    DielectricInterface interface;
    float probability[lobesFor<kF>()];
};

PT_HD bool isZero(Vec3 v) { return !(maxComponent(v) > 0.0f); }

// The specular (and glass) lobe's GGX alpha: stretched along x where kF has anisotropy.
template <FeatureSet kF>
PT_HD auto specularAlpha(const Lobes<kF>& l) {
    if constexpr (hasFeature<kF>(feature::kAnisotropy)) {
        return GgxAlpha2{l.alphaT, l.alpha};
    } else {
        return l.alpha;
    }
}

// Calls `use` with the glass lobe's Fresnel term: the exact one, or the exact one under a thin
// film where kF has iridescence and the material a film.
template <FeatureSet kF, class Use>
PT_HD auto withGlassFresnel(const Lobes<kF>& l, const Use& use) {
    if constexpr (hasFeature<kF>(feature::kIridescence)) {
        if (l.filmed.film.weight > 0.0f) return use(FilmedDielectricFresnel{l.filmed});
    }
    return use(ExactDielectricFresnel{});
}

// The specular lobe's Fresnel term: Schlick's, under a thin film where kF has iridescence.
template <FeatureSet kF>
PT_HD auto specularFresnel(const Lobes<kF>& l) {
    if constexpr (hasFeature<kF>(feature::kIridescence)) {
        return IridescentFresnel{l.specF0, l.specF90, l.filmed};
    } else {
        return SchlickFresnel{l.specF0, l.specF90};
    }
}

// Without feature::kGlossyReflection (kRoughTransmission) in kF, the scene's reflection (glass)
// lobes are all smooth, so the rough lobes' code is left out.
template <FeatureSet kF>
PT_HD bool isDeltaLobe(const Lobes<kF>& l, int lobe) {
    switch (lobe) {
        case kCoat: return ggxIsSmooth(l.coatAlpha);
        case kSpecular: return !hasFeature<kF>(feature::kGlossyReflection) || ggxIsSmooth(l.alpha);
        case kGlass: return !hasFeature<kF>(feature::kRoughTransmission) || dielectricIsSmooth(l.interface);
        default: return false;
    }
}

template <FeatureSet kF = kAllFeatures>
PT_HD Lobes<kF> resolveLobes(const BsdfParams& p, Vec3 wo) {
    constexpr bool kCoatLobe = hasFeature<kF>(feature::kClearcoat);
    constexpr bool kGlassLobe = hasFeature<kF>(feature::kTransmission);
    constexpr bool kDiffuseTransmissionLobe = hasFeature<kF>(feature::kDiffuseTransmission);
    constexpr bool kSheenLobe = hasFeature<kF>(feature::kSheen);
    constexpr bool kFilm = hasFeature<kF>(feature::kIridescence);
    Lobes<kF> l{};
    const bool front = wo.z > 0.0f;
    const float muO = front ? wo.z : 0.0f;
    const float metallic = clampf(p.metallic, 0.0f, 1.0f);
    const float transmission = kGlassLobe ? clampf(p.transmission, 0.0f, 1.0f) : 0.0f;
    const float specular = clampf(p.specular, 0.0f, 1.0f);
    const float ior = p.ior > 0.0f ? p.ior : 1.0f;
    const float opaque = (1.0f - metallic) * (1.0f - transmission);
    l.alpha = ggxAlpha(p.roughness);
    if constexpr (hasFeature<kF>(feature::kAnisotropy)) {
        // KHR_materials_anisotropy: alpha_t = mix(alpha, 1, strength^2), alpha_b = alpha, and
        // a lobe rough in either direction is rough in both (no zero alpha in D).
        l.alphaT = ggxAnisotropicAlpha(l.alpha, p.anisotropy);
        if (!ggxIsSmooth(l.alphaT)) l.alpha = fmaxf(l.alpha, kGgxSmoothAlpha);
    }
    l.coatAlpha = kCoatLobe ? ggxAlpha(p.clearcoatRoughness) : 0.0f;
    l.coat = kCoatLobe ? clearcoatWeight(p.clearcoat, muO) : 0.0f;
    float base = 1.0f - l.coat;
    float a[lobesFor<kF>()] = {};  // estimated albedos at wo: lobe selection in proportion to them
    if constexpr (kSheenLobe) {
        if (front && maxComponent(p.sheenColor) > 0.0f) {
            // The Charlie sheen reflects more than it receives at grazing views of smooth
            // fibres (sheen.h): there it is scaled to reflect all, and no more. What it
            // reflects the layers under it lose (the extension's albedo scaling).
            const float albedo = sheenAlbedo(muO, p.sheenRoughness);
            const float color = fminf(maxComponent(p.sheenColor), 1.0f);
            l.sheenAlpha = sheenAlpha(p.sheenRoughness);
            l.sheen = vmin(p.sheenColor, Vec3(1.0f)) * (base / fmaxf(albedo, 1.0f));
            a[kSheen] = base * color * fminf(albedo, 1.0f);
            base *= 1.0f - color * fminf(albedo, 1.0f);
        }
    }

    // KHR_materials_specular: F0 = min(F0(ior) specularColor, 1) specular, F90 = specular.
    l.layer.layerF0 =
        vmin(Vec3(dielectricF0(ior)) * vmax(p.specularColor, Vec3(0.0f)), Vec3(1.0f)) * specular;
    l.layer.layerF90 = Vec3(specular);
    l.layer.layerAlpha = l.alpha;

    const float transmitted = kDiffuseTransmissionLobe ? clampf(p.diffuseTransmission, 0.0f, 1.0f) : 0.0f;
    if constexpr (kFilm) {  // on the specular layer, the metal and the glass (from both sides)
        const float weight = p.iridescenceThickness > 0.0f ? clampf(p.iridescence, 0.0f, 1.0f) : 0.0f;
        if (weight > 0.0f) {
            l.filmed.film = {weight, fmaxf(p.iridescenceIor, 1.0f), p.iridescenceThickness};
            l.filmed.dielectricF0 =
                vmin(Vec3(dielectricF0(ior)) * vmax(p.specularColor, Vec3(0.0f)), Vec3(1.0f));
        }
    }
    if (front) {
        const Vec3 metalF0 = vmin(vmax(p.baseColor, Vec3(0.0f)), Vec3(1.0f));
        l.specF0 = (metalF0 * metallic + l.layer.layerF0 * opaque) * base;
        l.specF90 = (Vec3(metallic) + l.layer.layerF90 * opaque) * base;
        float filmTransmittance = 1.0f;  // what the film lets through of what the layer would
        if constexpr (kFilm) {
            const float weight = l.filmed.film.weight;
            if (weight > 0.0f) {
                l.filmed.metalF0 = metalF0;
                l.filmed.metalWeight = metallic * base;
                l.filmed.dielectricWeight = opaque * specular * base;
                // The film reflects more than the bare layer at some angles: the diffuse base
                // gets what it lets through at wo (as the specification's Fresnel mix does).
                const float bare = maxComponent(fresnelSchlick(l.layer.layerF0, l.layer.layerF90, muO));
                const Vec3 film = thinFilmFresnel(l.filmed.film, l.filmed.dielectricF0, muO) * specular;
                const float filmed = (1.0f - weight) * bare + weight * maxComponent(film);
                if (filmed > bare)
                    filmTransmittance = bare < 1.0f ? fmaxf(1.0f - filmed, 0.0f) / (1.0f - bare) : 0.0f;
            }
        }
        const SpecularAlbedo albedoO = ggxSpecularAlbedo(muO, l.alpha);
        a[kSpecular] = maxComponent(schlickAlbedo(albedoO, l.specF0, l.specF90));
        if (opaque > 0.0f) {
            const Vec3 transmittanceO = layerTransmittance(l.layer, albedoO) * filmTransmittance;
            const float reflected = base * opaque * (1.0f - transmitted);
            l.diffuse = p.baseColor * reflected * diffuseLayerScale(l.layer, transmittanceO);
            a[kDiffuse] = reflected * maxComponent(p.baseColor * transmittanceO);
            if constexpr (kDiffuseTransmissionLobe) {
                if (transmitted > 0.0f) {
                    l.diffuseTransmitted = vmax(p.diffuseTransmissionColor, Vec3(0.0f)) *
                                           (base * opaque * transmitted) * transmittanceO;
                    a[kDiffuseTransmission] = maxComponent(l.diffuseTransmitted);
                }
            }
        }
        if (kCoatLobe && l.coat > 0.0f) {
            const SpecularAlbedo coatAlbedo = ggxSpecularAlbedo(muO, l.coatAlpha);
            a[kCoat] = l.coat * (coatAlbedo.f0Part + coatAlbedo.f90Part);
        }
    }
    l.glass = (1.0f - metallic) * transmission * base;
    const Vec3 transmitTint = hasFeature<kF>(feature::kScatteringMedia)
                                  ? p.baseColor + (Vec3(1.0f) - p.baseColor) * p.untintedTransmission
                                  : p.baseColor;
    l.interface = {l.alpha, ior, vmin(p.specularColor * specular, Vec3(1.0f)), transmitTint};
    if (kGlassLobe && l.glass > 0.0f) {
        const float f = fresnelDielectric(fabsf(wo.z), relativeEta(l.interface, wo));
        const float transmit = maxComponent(l.interface.transmitTint);
        // Not below a tenth of the refracted share: rough microfacets refract where the
        // macro surface totally reflects.
        a[kGlass] = l.glass *
                    fmaxf(f * maxComponent(l.interface.reflectTint) + (1.0f - f) * transmit, 0.1f * transmit);
    }
    float sum = 0.0f;
    for (int i = 0; i < lobesFor<kF>(); ++i) sum += a[i] > 0.0f ? a[i] : 0.0f;
    for (int i = 0; i < lobesFor<kF>(); ++i) l.probability[i] = sum > 0.0f && a[i] > 0.0f ? a[i] / sum : 0.0f;
    return l;
}

// f * |cos(wi)| and the mixture pdf over the non-delta lobes, in the shading frame.
template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 evalLobes(const Lobes<kF>& l, Vec3 wo, Vec3 wi) {
    Vec3 f(0.0f);
    if (wo.z > 0.0f && wi.z > 0.0f) {
        if (hasFeature<kF>(feature::kClearcoat) && l.coat > 0.0f && !isDeltaLobe<kF>(l, kCoat))
            f += evalClearcoat(wo, wi, l.coatAlpha) * l.coat;
        if (!isZero(l.specF90 + l.specF0) && !isDeltaLobe<kF>(l, kSpecular)) {
            f += evalGgxReflection(wo, wi, specularAlpha(l), specularFresnel(l));
        }
        if (!isZero(l.diffuse)) f += evalLayeredDiffuse(l.layer, l.diffuse, wi);
    }
    if constexpr (hasFeature<kF>(feature::kDiffuseTransmission)) {
        if (wo.z > 0.0f && wi.z < 0.0f && !isZero(l.diffuseTransmitted))
            f += l.diffuseTransmitted * (-wi.z * kInvPi);
    }
    if constexpr (hasFeature<kF>(feature::kSheen)) {
        if (!isZero(l.sheen)) f += l.sheen * evalSheen(wo, wi, l.sheenAlpha);
    }
    if (hasFeature<kF>(feature::kTransmission) && l.glass > 0.0f && !isDeltaLobe<kF>(l, kGlass))
        f += withGlassFresnel(l,
                              [&](const auto& fresnel) {
                                  return evalRoughDielectric(l.interface, wo, wi, specularAlpha(l), fresnel);
                              }) *
             l.glass;
    return f;
}

template <FeatureSet kF = kAllFeatures>
PT_HD float pdfLobes(const Lobes<kF>& l, Vec3 wo, Vec3 wi) {
    float pdf = 0.0f;
    if (wo.z > 0.0f && wi.z > 0.0f) {
        if (hasFeature<kF>(feature::kClearcoat) && l.probability[kCoat] > 0.0f &&
            !isDeltaLobe<kF>(l, kCoat)) {
            pdf += l.probability[kCoat] * pdfGgxReflection(wo, wi, l.coatAlpha);
        }
        if (l.probability[kSpecular] > 0.0f && !isDeltaLobe<kF>(l, kSpecular)) {
            pdf += l.probability[kSpecular] * pdfGgxReflection(wo, wi, specularAlpha(l));
        }
        pdf += l.probability[kDiffuse] * cosineHemispherePdf(wi.z);
    }
    if constexpr (hasFeature<kF>(feature::kDiffuseTransmission)) {
        if (wo.z > 0.0f && wi.z < 0.0f)
            pdf += l.probability[kDiffuseTransmission] * cosineHemispherePdf(-wi.z);
    }
    if constexpr (hasFeature<kF>(feature::kSheen)) {
        if (wo.z > 0.0f && wi.z > 0.0f) pdf += l.probability[kSheen] * cosineHemispherePdf(wi.z);
    }
    if (hasFeature<kF>(feature::kTransmission) && l.probability[kGlass] > 0.0f &&
        !isDeltaLobe<kF>(l, kGlass)) {
        pdf += l.probability[kGlass] * withGlassFresnel(l, [&](const auto& fresnel) {
                   return pdfRoughDielectric(l.interface, wo, wi, specularAlpha(l), fresnel);
               });
    }
    return pdf;
}

// The rare lobes, both cosine-weighted. The sheen's lobe is broad, and sampling its half vectors
// would send most directions below the horizon (its distribution peaks at grazing h).
template <FeatureSet kF>
PT_HD LobeSample sampleRareLobe(const Lobes<kF>& l, int lobe, Vec3 wo, Vec2 uDir) {
    LobeSample s{};
    s.wi = squareToCosineHemisphere(uDir);
    if (lobe == kDiffuseTransmission) {
        s.wi.z = -s.wi.z;  // into the other hemisphere
        s.valid = wo.z > 0.0f && s.wi.z < 0.0f;
        s.pdf = cosineHemispherePdf(-s.wi.z);
        s.weight = l.diffuseTransmitted;  // the cos / pi cancel
        s.transmitted = true;
        return s;
    }
    s.valid = wo.z > 0.0f && s.wi.z > 0.0f;
    s.pdf = cosineHemispherePdf(s.wi.z);
    s.weight = s.valid ? l.sheen * (evalSheen(wo, s.wi, l.sheenAlpha) / s.pdf) : Vec3(0.0f);
    return s;
}

// Samples the chosen lobe alone; the weight includes the lobe's mix weight.
template <FeatureSet kF = kAllFeatures>
PT_HD LobeSample sampleLobe(const Lobes<kF>& l, int lobe, Vec3 wo, float uChoice, Vec2 uDir) {
    // Tested apart, so that code without them keeps the switch it had before they came.
    if constexpr ((kF & feature::kRareLobes) != 0u) {
        if (lobe >= kDiffuseTransmission) return sampleRareLobe(l, lobe, wo, uDir);
    }
    LobeSample s{};
    switch (lobe) {
        case kCoat:
            if (!hasFeature<kF>(feature::kClearcoat)) return s;
            s = isDeltaLobe<kF>(l, kCoat)
                    ? sampleSmoothReflection(wo, Vec3(1.0f), Vec3(1.0f))
                    : sampleGgxReflection(wo, l.coatAlpha, Vec3(1.0f), Vec3(1.0f), uDir);
            s.weight *= l.coat;
            return s;
        case kSpecular:
            if (!isDeltaLobe<kF>(l, kSpecular))
                return sampleGgxReflection(wo, specularAlpha(l), specularFresnel(l), uDir);
            return sampleSmoothReflection(wo, specularFresnel(l));
        case kDiffuse:
            s.wi = squareToCosineHemisphere(uDir);
            s.valid = wo.z > 0.0f && s.wi.z > 0.0f;
            s.pdf = cosineHemispherePdf(s.wi.z);
            s.weight = l.diffuse * layerTransmittance(l.layer, s.wi.z);  // the cos / pi cancel
            return s;
        default:
            if (!hasFeature<kF>(feature::kTransmission)) return s;
            s = withGlassFresnel(l, [&](const auto& fresnel) {
                return isDeltaLobe<kF>(l, kGlass)
                           ? sampleSmoothDielectric(l.interface, wo, uChoice, fresnel)
                           : sampleRoughDielectric(l.interface, wo, uChoice, uDir, specularAlpha(l), fresnel);
            });
            s.weight *= l.glass;
            return s;
    }
}

// How many non-delta lobes can be picked.
template <FeatureSet kF>
PT_HD int nonDeltaLobeCount(const Lobes<kF>& l) {
    int n = 0;
    for (int i = 0; i < lobesFor<kF>(); ++i) n += l.probability[i] > 0.0f && !isDeltaLobe<kF>(l, i) ? 1 : 0;
    return n;
}

}  // namespace bsdf_detail

// f(wo, wi) |cos(wi)| for the non-delta lobes. wo, wi in world space.
template <FeatureSet kF = kAllFeatures>
PT_HD Vec3 evalBsdf(const BsdfParams& p, const Frame& frame, Vec3 woWorld, Vec3 wiWorld) {
    const Vec3 wo = frame.toLocal(woWorld);
    return bsdf_detail::evalLobes<kF>(bsdf_detail::resolveLobes<kF>(p, wo), wo, frame.toLocal(wiWorld));
}

// Solid-angle density with which sampleBsdf() picks wi through its non-delta lobes.
template <FeatureSet kF = kAllFeatures>
PT_HD float pdfBsdf(const BsdfParams& p, const Frame& frame, Vec3 woWorld, Vec3 wiWorld) {
    const Vec3 wo = frame.toLocal(woWorld);
    return bsdf_detail::pdfLobes<kF>(bsdf_detail::resolveLobes<kF>(p, wo), wo, frame.toLocal(wiWorld));
}

// evalBsdf() and pdfBsdf() together, resolving the lobes once: what light sampling needs.
struct BsdfEval {
    Vec3 value;  // f(wo, wi) |cos(wi)|
    float pdf;   // as pdfBsdf()
};
template <FeatureSet kF = kAllFeatures>
PT_HD BsdfEval evalBsdfWithPdf(const BsdfParams& p, const Frame& frame, Vec3 woWorld, Vec3 wiWorld) {
    const Vec3 wo = frame.toLocal(woWorld), wi = frame.toLocal(wiWorld);
    const bsdf_detail::Lobes<kF> lobes = bsdf_detail::resolveLobes<kF>(p, wo);
    return {bsdf_detail::evalLobes<kF>(lobes, wo, wi), bsdf_detail::pdfLobes<kF>(lobes, wo, wi)};
}

// Whether evalBsdf() can be non-zero for some pair of directions (light sampling pays off).
template <FeatureSet kF = kAllFeatures>
PT_HD bool hasNonDeltaLobes(const BsdfParams& p) {
    const float metallic = clampf(p.metallic, 0.0f, 1.0f);
    const float transmission =
        hasFeature<kF>(feature::kTransmission) ? clampf(p.transmission, 0.0f, 1.0f) : 0.0f;
    const float opaque = (1.0f - metallic) * (1.0f - transmission);
    float alpha = ggxAlpha(p.roughness);
    if (hasFeature<kF>(feature::kAnisotropy))
        alpha = ggxAnisotropicAlpha(alpha, p.anisotropy);  // the rougher
    if (opaque > 0.0f && maxComponent(p.baseColor) > 0.0f) return true;
    if (hasFeature<kF>(feature::kDiffuseTransmission) && opaque > 0.0f && p.diffuseTransmission > 0.0f &&
        maxComponent(p.diffuseTransmissionColor) > 0.0f)
        return true;
    if (hasFeature<kF>(feature::kClearcoat) && p.clearcoat > 0.0f &&
        !ggxIsSmooth(ggxAlpha(p.clearcoatRoughness)))
        return true;
    if (hasFeature<kF>(feature::kSheen) && maxComponent(p.sheenColor) > 0.0f) return true;
    if (ggxIsSmooth(alpha)) return false;
    const float ior = p.ior > 0.0f ? p.ior : 1.0f;
    return metallic > 0.0f || (opaque > 0.0f && p.specular > 0.0f) ||
           (transmission > 0.0f && !dielectricIsSmooth({alpha, ior, Vec3(1.0f), Vec3(1.0f)}));
}

// Picks a lobe with `uLobe` (the remainder of which chooses reflection or refraction in the
// glass lobe), then a direction with `uDir`. A zero weight means no sample.
template <FeatureSet kF = kAllFeatures>
PT_HD BsdfSample sampleBsdf(const BsdfParams& p, const Frame& frame, Vec3 woWorld, float uLobe, Vec2 uDir) {
    using namespace bsdf_detail;
    const Vec3 wo = frame.toLocal(woWorld);
    const Lobes<kF> l = resolveLobes<kF>(p, wo);
    BsdfSample s{};
    int lobe = -1;
    float start = 0.0f, next = 0.0f;
    for (int i = 0; i < lobesFor<kF>(); ++i) {
        if (l.probability[i] <= 0.0f) continue;
        lobe = i;  // the last lobe with a probability catches rounding past the sum
        start = next;
        next = start + l.probability[i];
        if (uLobe < next) break;
    }
    if (lobe < 0) return s;
    const float uChoice = clampf((uLobe - start) / l.probability[lobe], 0.0f, 0.99999994f);
    const LobeSample ls = sampleLobe<kF>(l, lobe, wo, uChoice, uDir);
    if (!ls.valid) return s;
    s.wi = frame.toWorld(ls.wi);
    s.transmitted = ls.transmitted;
    s.refracted = ls.transmitted && ((kF & feature::kDiffuseTransmission) == 0u || lobe == kGlass);
    if (ls.delta) {
        s.delta = true;
        s.weight = ls.weight * (1.0f / l.probability[lobe]);
        return s;
    }
    if (nonDeltaLobeCount<kF>(l) == 1) {  // no other lobe's density to combine with
        s.pdf = l.probability[lobe] * ls.pdf;
        s.weight = ls.weight * (1.0f / l.probability[lobe]);
        return s;
    }
    const float pdf = pdfLobes<kF>(l, wo, ls.wi);
    if (!(pdf > 0.0f)) return s;
    s.pdf = pdf;
    s.weight = evalLobes<kF>(l, wo, ls.wi) / pdf;
    return s;
}

}  // namespace pt
