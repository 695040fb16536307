#pragma once
// KHR_materials_sheen: the "Charlie" sheen of Estevez and Kulla 2017 ("Production Friendly
// Microfacet Sheen BRDF", SIGGRAPH course), the glTF extension's model. Fibres standing on the
// surface reflect at grazing half vectors: the distribution is an inverted sine,
//   D(h) = (2 + 1/a) sin(theta_h)^(1/a) / (2 pi),   a = sheenRoughness^2
// (squared as in Khronos' glTF Sample Viewer), with the paper's fitted shadowing Lambda and the
// height-correlated visibility V = 1 / ((1 + Lambda(mu_o) + Lambda(mu_i)) 4 mu_o mu_i). No
// Fresnel term (the extension's choice). The layer under the sheen keeps
// 1 - max(sheenColor) E(mu_o) of its light, the extension's albedo scaling in its one-sided form,
// with E, the sheen's own directional albedo, from sheen_albedo_table.h.
#include "render/materials/sheen_albedo_table.h"
#include "render/math/vec.h"

namespace pt {

// Below this sheen roughness the distribution's peak at grazing half vectors grows narrower
// than the albedo table resolves (a = 0.0049, an exponent of 204).
constexpr float kMinSheenRoughness = 0.07f;

PT_HD float sheenAlpha(float sheenRoughness) {
    const float r = clampf(sheenRoughness, kMinSheenRoughness, 1.0f);
    return r * r;
}

// D(h) from cos(theta_h).
PT_HD float charlieDistribution(float cosH, float alpha) {
    const float sin2 = fmaxf(1.0f - cosH * cosH, 0.0f);
    if (!(sin2 > 0.0f)) return 0.0f;
    const float invAlpha = 1.0f / alpha;
    return (2.0f + invAlpha) * expf(0.5f * invAlpha * logf(sin2)) * (0.5f * kInvPi);
}

namespace sheen_detail {
// The paper's fit of log Lambda, its coefficients interpolated in (1 - a)^2.
PT_HD float logLambdaFit(float x, float alpha) {
    const float t = (1.0f - alpha) * (1.0f - alpha);
    const float a = 21.5473f + (25.3245f - 21.5473f) * t;
    const float b = 3.82987f + (3.32435f - 3.82987f) * t;
    const float c = 0.19823f + (0.16801f - 0.19823f) * t;
    const float d = -1.97760f + (-1.27393f + 1.97760f) * t;
    const float e = -4.32054f + (-4.85967f + 4.32054f) * t;
    const float xc = x > 0.0f ? expf(c * logf(x)) : 0.0f;
    return a / (1.0f + b * xc) + d * x + e;
}
}  // namespace sheen_detail

// Lambda(mu): the fit for mu < 0.5, mirrored about 0.5 above it (the paper's form).
PT_HD float charlieLambda(float mu, float alpha) {
    using sheen_detail::logLambdaFit;
    mu = clampf(mu, 0.0f, 1.0f);
    if (mu < 0.5f) return expf(logLambdaFit(mu, alpha));
    return expf(2.0f * logLambdaFit(0.5f, alpha) - logLambdaFit(1.0f - mu, alpha));
}

// f(wo, wi) |cos(wi)| of a white sheen, in the shading frame (both above the surface). The
// visibility is clamped to 1, as the Sample Viewer does: the fitted Lambda stays finite at
// grazing angles, so without the clamp f |cos| would grow as 1 / mu_o there.
PT_HD float evalSheen(Vec3 wo, Vec3 wi, float alpha) {
    if (!(wo.z > 0.0f) || !(wi.z > 0.0f)) return 0.0f;
    const Vec3 h = normalize(wo + wi);
    const float denominator =
        4.0f * wo.z * wi.z * (1.0f + charlieLambda(wo.z, alpha) + charlieLambda(wi.z, alpha));
    const float visibility = denominator > 1.0f ? 1.0f / denominator : 1.0f;
    return charlieDistribution(h.z, alpha) * visibility * wi.z;
}

// E(mu): the directional albedo of a white sheen seen at cos(theta) = mu, bilinear in
// (sqrt(mu), sheen roughness) over the generated table. It exceeds 1 at grazing views of smooth
// sheens (1.6 at roughness 0.07 and mu = 0.001: the fitted Lambda shadows too little there).
PT_HD float sheenAlbedo(float mu, float sheenRoughness) {
    using namespace sheen_albedo_detail;
    const float x = sqrtf(clampf(mu, 0.0f, 1.0f)) * float(kMuCount - 1);  // dense at grazing
    const float y = (clampf(sheenRoughness, kMinSheenRoughness, 1.0f) - kMinSheenRoughness) /
                    (1.0f - kMinSheenRoughness) * float(kRoughnessCount - 1);
    const int i = x < float(kMuCount - 2) ? int(x) : kMuCount - 2;
    const int j = y < float(kRoughnessCount - 2) ? int(y) : kRoughnessCount - 2;
    const float fx = x - float(i), fy = y - float(j);
    const auto& e = kSheenAlbedoTable.e;
    const float lo = e[j][i] + (e[j][i + 1] - e[j][i]) * fx;
    const float hi = e[j + 1][i] + (e[j + 1][i + 1] - e[j + 1][i]) * fx;
    return lo + (hi - lo) * fy;
}

}  // namespace pt
