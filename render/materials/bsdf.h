#pragma once
// The surface BSDF of a Material at one shading point, in the shading frame (local z is
// the shading normal, pointing to the front side). It is a mixture of lobes chosen by the
// glTF parameters:
//   diffuse    (1 - metallic)(1 - transmission)   Lambertian, baseColor
//   mirror     metallic                           perfect specular conductor, Schlick F0 = baseColor
//   glass      (1 - metallic) transmission        smooth dielectric, exact Fresnel, IOR
// Roughness and the dielectric specular layer of glTF's model arrive with the GGX lobes
// (materials issue); until then rough metals render as mirrors.
#include "render/materials/fresnel.h"
#include "render/math/frame.h"
#include "render/sampling/warp.h"

namespace pt {

struct BsdfParams {
    Vec3 baseColor;
    float metallic;
    float transmission;
    float ior;
};

struct BsdfSample {
    Vec3 wi;         // world space, unit
    Vec3 weight;     // f * |cos| / pdf
    float pdf;       // solid-angle density; meaningless when `delta`
    bool delta;      // from a specular lobe: no light sampling, no MIS
    bool transmitted;
};

struct LobeWeights {
    float diffuse, mirror, glass;
};

PT_HD LobeWeights lobeWeights(const BsdfParams& p) {
    const float m = clampf(p.metallic, 0.0f, 1.0f), t = clampf(p.transmission, 0.0f, 1.0f);
    return {(1.0f - m) * (1.0f - t), m, (1.0f - m) * t};
}

// f(wo, wi) |cos(wi)| for the non-delta lobes. wo, wi in world space.
PT_HD Vec3 evalBsdf(const BsdfParams& p, const Frame& frame, Vec3 woWorld, Vec3 wiWorld) {
    const Vec3 wo = frame.toLocal(woWorld), wi = frame.toLocal(wiWorld);
    if (wo.z <= 0.0f || wi.z <= 0.0f) return Vec3(0.0f);  // diffuse reflects on the front only
    return p.baseColor * (lobeWeights(p).diffuse * kInvPi * wi.z);
}

// Solid-angle density with which sampleBsdf() picks wi through its non-delta lobes.
PT_HD float pdfBsdf(const BsdfParams& p, const Frame& frame, Vec3 woWorld, Vec3 wiWorld) {
    const Vec3 wo = frame.toLocal(woWorld), wi = frame.toLocal(wiWorld);
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    return lobeWeights(p).diffuse * cosineHemispherePdf(wi.z);
}

PT_HD bool hasNonDeltaLobes(const BsdfParams& p) { return lobeWeights(p).diffuse > 0.0f; }

PT_HD BsdfSample sampleGlass(const BsdfParams& p, const Frame& frame, Vec3 wo, float uChoice) {
    const bool entering = wo.z > 0.0f;
    const float eta = entering ? p.ior : 1.0f / p.ior;  // eta_t / eta_i
    const float cosO = fabsf(wo.z);
    const float fresnel = fresnelDielectric(cosO, eta);
    BsdfSample s{};
    s.delta = true;
    s.pdf = 0.0f;
    if (uChoice < fresnel) {
        s.wi = frame.toWorld({-wo.x, -wo.y, wo.z});
        s.weight = Vec3(1.0f);
        return s;
    }
    Vec3 wt;
    const Vec3 n{0.0f, 0.0f, entering ? 1.0f : -1.0f};
    if (!refractDirection(wo, n, eta, wt)) {  // unreachable when fresnel == 1, kept for safety
        s.wi = frame.toWorld({-wo.x, -wo.y, wo.z});
        s.weight = Vec3(1.0f);
        return s;
    }
    s.wi = frame.toWorld(normalize(wt));
    // Radiance is compressed by 1/eta^2 crossing into the denser side (Veach 1997, 5.2).
    s.weight = p.baseColor * (1.0f / (eta * eta));
    s.transmitted = true;
    return s;
}

// Picks a lobe with `uLobe`, then a direction with `uDir`. A zero weight means no sample.
PT_HD BsdfSample sampleBsdf(const BsdfParams& p, const Frame& frame, Vec3 woWorld, float uLobe,
                            Vec2 uDir) {
    const Vec3 wo = frame.toLocal(woWorld);
    const LobeWeights w = lobeWeights(p);
    BsdfSample s{};
    if (uLobe < w.glass) {
        return sampleGlass(p, frame, wo, uDir.x);
    }
    if (wo.z <= 0.0f) return s;  // opaque lobes see only the front
    if (uLobe < w.glass + w.mirror) {
        s.wi = frame.toWorld({-wo.x, -wo.y, wo.z});
        s.weight = fresnelSchlick(p.baseColor, wo.z);
        s.delta = true;
        return s;
    }
    const Vec3 wi = squareToCosineHemisphere(uDir);
    if (wi.z <= 0.0f) return s;
    s.wi = frame.toWorld(wi);
    s.pdf = w.diffuse * cosineHemispherePdf(wi.z);
    s.weight = p.baseColor;  // (w.diffuse * albedo / pi * cos) / (w.diffuse * cos / pi)
    return s;
}

}  // namespace pt
