#pragma once
#include "render/math/vec.h"

namespace pt {

// Unpolarised Fresnel reflectance of a smooth dielectric interface. `cosThetaI` is the cosine
// on the incident side (>= 0); `eta` = eta_transmitted / eta_incident. Total internal
// reflection returns 1.
PT_HD float fresnelDielectric(float cosThetaI, float eta) {
    cosThetaI = clampf(cosThetaI, 0.0f, 1.0f);
    const float sin2ThetaT = (1.0f - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2ThetaT >= 1.0f) return 1.0f;
    const float cosThetaT = sqrtf(fmaxf(0.0f, 1.0f - sin2ThetaT));
    const float rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    const float rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return 0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

// (1 - cos)^5, the angular factor of Schlick's approximation.
PT_HD float schlickWeight(float cosTheta) {
    const float m = clampf(1.0f - cosTheta, 0.0f, 1.0f);
    return (m * m) * (m * m) * m;
}

// Schlick's approximation with the reflectance `f0` at normal incidence and `f90` at grazing
// (glTF Appendix B; KHR_materials_specular lowers f90 of dielectrics).
PT_HD Vec3 fresnelSchlick(Vec3 f0, Vec3 f90, float cosTheta) {
    return f0 + (f90 - f0) * schlickWeight(cosTheta);
}

// Schlick's approximation for conductors, with the reflectance at normal incidence `f0`.
PT_HD Vec3 fresnelSchlick(Vec3 f0, float cosTheta) { return fresnelSchlick(f0, Vec3(1.0f), cosTheta); }

// Reflectance at normal incidence of an interface between indices 1 and `ior`.
PT_HD float dielectricF0(float ior) {
    const float r = (ior - 1.0f) / (ior + 1.0f);
    return r * r;
}

// Refracts `wi` (pointing away from the surface, on the side `n` points to) through an
// interface of relative index `eta` = eta_transmitted / eta_incident. False on total internal
// reflection.
PT_HD bool refractDirection(Vec3 wi, Vec3 n, float eta, Vec3& wt) {
    const float cosThetaI = dot(n, wi);
    const float sin2ThetaT = fmaxf(0.0f, 1.0f - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2ThetaT >= 1.0f) return false;
    const float cosThetaT = sqrtf(1.0f - sin2ThetaT);
    wt = -wi / eta + n * (cosThetaI / eta - cosThetaT);
    return true;
}

}  // namespace pt
