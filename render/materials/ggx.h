#pragma once
// The isotropic Trowbridge-Reitz (GGX) microfacet distribution with the height-correlated
// Smith masking-shadowing function, and sampling of its visible normals.
//
// Directions live in the shading frame (z = macro normal). KHR_materials_anisotropy's
// anisotropic form takes GgxAlpha2, one alpha along the frame's x and one along its y (Heitz
// 2014, "Understanding the Masking-Shadowing Function", eqs. 85 and 86); the float overloads are
// the isotropic functions every other lobe uses, unchanged. glTF maps roughness r to
// alpha = r^2. Below kGgxSmoothAlpha a lobe is treated as perfectly smooth (a delta lobe):
// the density of the rough model would exceed what float can resolve (pbrt-v4 does the same).
//
// Masking is written with a(w) = sqrt(cos^2 + alpha^2 sin^2) = |cos| (1 + 2 Lambda(w)), so that
//   G1(w) / |cos w|        = 2 / (|cos w| + a(w))
//   G2(o, i) / (4 |cos o| |cos i|) = 1 / (2 (|cos i| a(o) + |cos o| a(i)))
// stay finite at grazing angles instead of dividing two vanishing numbers.
#include "render/math/vec.h"

namespace pt {

constexpr float kGgxSmoothAlpha = 1e-3f;

// Anisotropic roughness: alpha along the shading frame's x (the anisotropy direction) and y.
struct GgxAlpha2 {
    float x, y;
};
// The alpha along x and y of either kind.
PT_HD float alphaX(float alpha) { return alpha; }
PT_HD float alphaY(float alpha) { return alpha; }
PT_HD float alphaX(GgxAlpha2 alpha) { return alpha.x; }
PT_HD float alphaY(GgxAlpha2 alpha) { return alpha.y; }

PT_HD float ggxAlpha(float roughness) {
    const float r = clampf(roughness, 0.0f, 1.0f);
    return r * r;
}
PT_HD bool ggxIsSmooth(float alpha) { return !(alpha >= kGgxSmoothAlpha); }

// Normal distribution D(m) for a unit microfacet normal m; zero below the macro surface.
PT_HD float ggxD(Vec3 m, float alpha) {
    if (m.z <= 0.0f) return 0.0f;
    const float a2 = alpha * alpha;
    const float d = (m.x * m.x + m.y * m.y) / a2 + m.z * m.z;
    return 1.0f / (kPi * a2 * d * d);
}

// a(w) = |cos w| (1 + 2 Lambda(w)).
PT_HD float ggxMaskingTerm(Vec3 w, float alpha) {
    return sqrtf(w.z * w.z + alpha * alpha * (w.x * w.x + w.y * w.y));
}

// Height-correlated G2(o, i) (Heitz 2014, eq. 99); both cosines taken in absolute value.
template <class Alpha>
PT_HD float ggxG2(Vec3 wo, Vec3 wi, Alpha alpha) {
    const float muO = fabsf(wo.z), muI = fabsf(wi.z);
    const float denom = muI * ggxMaskingTerm(wo, alpha) + muO * ggxMaskingTerm(wi, alpha);
    return denom > 0.0f ? 2.0f * muO * muI / denom : 0.0f;
}

// Density of visible normals m seen from wo (wo.z >= 0), per solid angle of m:
// G1(wo) max(0, wo.m) D(m) / cos(wo).
template <class Alpha>
PT_HD float ggxVisibleNormalPdf(Vec3 wo, Vec3 m, Alpha alpha) {
    const float cosOM = dot(wo, m);
    if (cosOM <= 0.0f) return 0.0f;
    return 2.0f * cosOM * ggxD(m, alpha) / (wo.z + ggxMaskingTerm(wo, alpha));
}

// A visible normal seen from wo (wo.z >= 0), distributed as ggxVisibleNormalPdf. Spherical-cap
// formulation of Dupuy and Benyoub, "Sound and Robust Sampling of the GGX Distribution of
// Visible Normals" (2023), which is exact at every incidence including wo.z == 0.
// `alpha` is a float or (stretched by each alpha along its axis) a GgxAlpha2.
template <class Alpha>
PT_HD Vec3 sampleGgxVisibleNormal(Vec3 wo, Alpha alpha, Vec2 u) {
    // Stretch the view into the configuration where alpha == 1 (a hemisphere of normals).
    const Vec3 v = normalize(Vec3{alphaX(alpha) * wo.x, alphaY(alpha) * wo.y, wo.z});
    const float phi = 2.0f * kPi * u.x;
    const float z = (1.0f - u.y) * (1.0f + v.z) - v.z;
    const float sinTheta = sqrtf(clampf(1.0f - z * z, 0.0f, 1.0f));
    const Vec3 h = Vec3{sinTheta * cosf(phi), sinTheta * sinf(phi), z} + v;
    // Unstretch; h.z >= 0 by construction, and only a measure-zero set of u gives h == 0.
    const Vec3 m{alphaX(alpha) * h.x, alphaY(alpha) * h.y, fmaxf(h.z, 0.0f)};
    const float len2 = lengthSquared(m);
    if (!(len2 > 1e-30f)) return {0.0f, 0.0f, 1.0f};
    return m * (1.0f / sqrtf(len2));
}

// KHR_materials_anisotropy's alpha along its direction: mix(alpha, 1, strength^2).
PT_HD float ggxAnisotropicAlpha(float alpha, float strength) {
    const float s = clampf(strength, 0.0f, 1.0f);
    return alpha + (1.0f - alpha) * s * s;
}

// Smooth only if smooth in both directions; a rough anisotropic lobe keeps both alphas at or
// above kGgxSmoothAlpha (bsdf.h).
PT_HD bool ggxIsSmooth(GgxAlpha2 alpha) { return ggxIsSmooth(fmaxf(alpha.x, alpha.y)); }

PT_HD float ggxD(Vec3 m, GgxAlpha2 alpha) {
    if (m.z <= 0.0f) return 0.0f;
    const float sx = m.x / alpha.x, sy = m.y / alpha.y;
    const float d = sx * sx + sy * sy + m.z * m.z;
    return 1.0f / (kPi * alpha.x * alpha.y * d * d);
}

PT_HD float ggxMaskingTerm(Vec3 w, GgxAlpha2 alpha) {
    const float sx = alpha.x * w.x, sy = alpha.y * w.y;
    return sqrtf(w.z * w.z + sx * sx + sy * sy);
}

}  // namespace pt
