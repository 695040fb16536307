#pragma once
// Directional albedo E(mu) of the single-scattering GGX reflection lobe with Schlick's Fresnel,
// the energy a specular layer takes away from the layer under it.
//
// Schlick's F = F0 + (F90 - F0)(1 - c)^5 is linear in F0 and F90, so two scalar tables give the
// albedo of every F0 and F90: E(mu) = F0 p(mu) + F90 b(mu). The tables are bilinear over
// x = mu^(1/3) (dense near grazing, where small roughness changes fastest) and roughness.
// They are conservative: generated so that the interpolant bounds the true albedo from above
// (tests/render/materials/specular_albedo_test.cpp regenerates and checks them). The cosine-
// weighted hemispherical averages are integrals of the interpolant itself, so a layer scaled by
// (1 - E(mu_o))(1 - E(mu_i)) / (1 - E_avg) reflects exactly (1 - E(mu_o)) of a white diffuse.
// Smooth lobes (alpha below kGgxSmoothAlpha) use the exact values, E = F(mu).
#include "render/materials/ggx.h"
#include "render/materials/specular_albedo_table.h"

namespace pt {

struct SpecularAlbedo {
    float f0Part, f90Part;  // E = F0 * f0Part + F90 * f90Part
};

namespace specular_albedo_detail {
constexpr float kMinRoughness = 0.031622776601683794f;  // sqrt(kGgxSmoothAlpha)

PT_HD float gridMu(int i) {
    const float x = float(i) / float(kMuCount - 1);
    return x * x * x;
}
PT_HD float gridRoughness(int j) {
    return kMinRoughness + (1.0f - kMinRoughness) * float(j) / float(kRoughnessCount - 1);
}
PT_HD void cell(float t, int count, int& i, float& f) {
    t = clampf(t, 0.0f, float(count - 1));
    i = int(t);
    if (i > count - 2) i = count - 2;
    f = t - float(i);
}
// mu^(1/3) from basic arithmetic only (bit-level first guess, two Newton steps; relative error
// below 1e-6): faster than libm's cbrtf and rounded identically by every compiler.
PT_HD float cubeRoot(float mu) {
    if (!(mu > 1e-30f)) return 0.0f;
    float x = intAsFloat(floatAsInt(mu) / 3 + 709921077);
    x = x - (x * x * x - mu) / (3.0f * x * x);
    x = x - (x * x * x - mu) / (3.0f * x * x);
    return x;
}
PT_HD float roughnessCoordinate(float alpha) {
    return (sqrtf(alpha) - kMinRoughness) / (1.0f - kMinRoughness) * float(kRoughnessCount - 1);
}
}  // namespace specular_albedo_detail

PT_HD SpecularAlbedo ggxSpecularAlbedo(float mu, float alpha) {
    using namespace specular_albedo_detail;
    mu = clampf(mu, 0.0f, 1.0f);
    if (ggxIsSmooth(alpha)) {
        const float m = 1.0f - mu, m5 = (m * m) * (m * m) * m;
        return {1.0f - m5, m5};
    }
    int i, j;
    float fx, fy;
    cell(cubeRoot(mu) * float(kMuCount - 1), kMuCount, i, fx);
    cell(roughnessCoordinate(alpha), kRoughnessCount, j, fy);
    const auto& t = kSpecularAlbedoTables;
    auto bilinear = [&](const float(&v)[kRoughnessCount][kMuCount]) {
        const float lo = v[j][i] + (v[j][i + 1] - v[j][i]) * fx;
        const float hi = v[j + 1][i] + (v[j + 1][i + 1] - v[j + 1][i]) * fx;
        return lo + (hi - lo) * fy;
    };
    return {bilinear(t.p), bilinear(t.b)};
}

// 2 * integral of E(mu) mu dmu over [0, 1].
PT_HD SpecularAlbedo ggxSpecularAlbedoAverage(float alpha) {
    using namespace specular_albedo_detail;
    if (ggxIsSmooth(alpha)) return {20.0f / 21.0f, 1.0f / 21.0f};  // 2 * int (1-mu)^5 mu = 1/21
    int j;
    float fy;
    cell(roughnessCoordinate(alpha), kRoughnessCount, j, fy);
    const auto& t = kSpecularAlbedoTables;
    return {t.pAverage[j] + (t.pAverage[j + 1] - t.pAverage[j]) * fy,
            t.bAverage[j] + (t.bAverage[j + 1] - t.bAverage[j]) * fy};
}

PT_HD Vec3 schlickAlbedo(SpecularAlbedo a, Vec3 f0, Vec3 f90) { return f0 * a.f0Part + f90 * a.f90Part; }

}  // namespace pt
