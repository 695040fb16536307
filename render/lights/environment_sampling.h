#pragma once
// Sampling directions towards the environment, and the density of a given direction, for
// next-event estimation and for the MIS weight of BSDF-sampled rays that miss the scene.
//
// An image is sampled through a piecewise-constant 2D distribution on the equirect square
// (pbrt-v4's PiecewiseConstant2D): a row by the marginal CDF, then a column by that row's
// conditional CDF, then a uniform point in the cell. Cell weights are the mean radiance of
// the bilinear reconstruction over the cell times sin(theta), built on the host
// (environment_distribution.h). The solid-angle density is p(u, v) / (2 pi^2 sin(theta)).
// A constant environment is sampled uniformly over the sphere.
#include "render/lights/environment.h"
#include "render/sampling/warp.h"

namespace pt {

// Index i in [0, n) with cdf[i] <= u < cdf[i + 1]; cdf has n + 1 entries, cdf[0] = 0, cdf[n] = 1.
PT_HD uint32_t findCdfInterval(const float* cdf, uint32_t n, float u) {
    uint32_t lo = 0, hi = n;  // invariant: cdf[lo] <= u < cdf[hi] (cdf[n] = 1 > u)
    while (hi - lo > 1) {
        const uint32_t mid = (lo + hi) / 2;
        if (cdf[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

// A continuous sample in [0, 1) from a piecewise-constant distribution given by its CDF.
PT_HD float samplePiecewiseConstant(const float* cdf, uint32_t n, float u, uint32_t& index) {
    index = findCdfInterval(cdf, n, u);
    const float width = cdf[index + 1] - cdf[index];
    const float frac = width > 0.0f ? clampf((u - cdf[index]) / width, 0.0f, 0.99999994f) : 0.5f;
    return (float(index) + frac) / float(n);
}

template <FeatureSet kF = kAllFeatures>
PT_HD bool environmentIsImportanceSampled(const RenderScene& scene) {
    return hasFeature<kF>(feature::kImageEnvironment) && scene.environment.texture >= 0 &&
           scene.environment.distWidth > 0;
}

// Density over solid angle with which sampleEnvironmentDirection() picks `direction` (unit).
template <FeatureSet kF = kAllFeatures>
PT_HD float environmentDirectionPdf(const RenderScene& scene, Vec3 direction) {
    const RenderEnvironment& env = scene.environment;
    if (!environmentIsImportanceSampled<kF>(scene)) return 1.0f / (4.0f * kPi);
    // From x and z rather than 1 - y^2, which rounds to 0 within 3e-4 radians of a pole.
    const float sinTheta = sqrtf(direction.x * direction.x + direction.z * direction.z);
    if (!(sinTheta > 0.0f)) return 0.0f;
    const Vec2 uv = directionToEquirect(direction, env.rotationRadians);
    const uint32_t x = uint32_t(fminf(uv.x * float(env.distWidth), float(env.distWidth - 1)));
    const uint32_t y = uint32_t(fminf(uv.y * float(env.distHeight), float(env.distHeight - 1)));
    return scene.envPdf[y * env.distWidth + x] / (2.0f * kPi * kPi * sinTheta);
}

// A direction towards the environment and its solid-angle density; false when none.
template <FeatureSet kF = kAllFeatures>
PT_HD bool sampleEnvironmentDirection(const RenderScene& scene, Vec2 u, Vec3& direction, float& pdf) {
    const RenderEnvironment& env = scene.environment;
    if (!environmentIsImportanceSampled<kF>(scene)) {
        const float z = 1.0f - 2.0f * u.x;
        const float r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
        const float phi = 2.0f * kPi * u.y;
        direction = {r * cosf(phi), r * sinf(phi), z};
        pdf = 1.0f / (4.0f * kPi);
        return true;
    }
    uint32_t row, column;
    const float v = samplePiecewiseConstant(scene.envMarginalCdf.data, env.distHeight, u.y, row);
    const float* conditional = scene.envConditionalCdf.data + size_t(row) * (env.distWidth + 1);
    const float uu = samplePiecewiseConstant(conditional, env.distWidth, u.x, column);
    const float theta = v * kPi;
    const float sinTheta = sinf(theta);
    if (!(sinTheta > 0.0f)) return false;
    direction = equirectToDirection({uu, v}, env.rotationRadians);
    pdf = scene.envPdf[row * env.distWidth + column] / (2.0f * kPi * kPi * sinTheta);
    return pdf > 0.0f;
}

}  // namespace pt
