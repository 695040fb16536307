#pragma once
// KHR_materials_clearcoat: a white GGX layer (index 1.5, F0 = 0.04) over the whole material,
// mixed as the extension specifies,
//   coated = mix(material, clearcoat_brdf, clearcoat * Fresnel(0.04, N.V)),
// i.e. the base is scaled by 1 - w(mu_o) and the coat's specular_brdf (D G2 / (4 cos cos), no
// Fresnel inside) by w(mu_o). Both parts reflect at most 1, so the mix never gains energy. The
// weight depends on the view only, so the coated material is not reciprocal (by the spec's
// design). The coat shares the shading normal (clearcoat normal maps are not imported).
#include "render/materials/microfacet_reflection.h"

namespace pt {

constexpr float kClearcoatF0 = 0.04f;

// The mix weight w(mu_o) = clearcoat * Schlick(0.04, mu_o); front side only.
PT_HD float clearcoatWeight(float clearcoat, float cosO) {
    if (!(clearcoat > 0.0f) || cosO <= 0.0f) return 0.0f;
    return clampf(clearcoat, 0.0f, 1.0f) * (kClearcoatF0 + (1.0f - kClearcoatF0) * schlickWeight(cosO));
}

// The coat's BRDF times cos(wi) (without the mix weight).
PT_HD Vec3 evalClearcoat(Vec3 wo, Vec3 wi, float alpha) {
    return evalGgxReflection(wo, wi, alpha, Vec3(1.0f), Vec3(1.0f));
}

}  // namespace pt
