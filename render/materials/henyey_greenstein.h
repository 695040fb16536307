#pragma once
// The Henyey-Greenstein phase function (Henyey and Greenstein 1941), the scattering lobe of the
// homogeneous media of issue 15 (fog, skin, wax, jade): one parameter g in (-1, 1), the mean
// cosine of the scattering angle (g > 0 forward, g < 0 back, 0 isotropic). Directions are
// propagation directions: `cosTheta` is the cosine between the direction the light travelled
// in and the one it leaves along, so forward scattering keeps cosTheta near 1.
//
//   p(cosTheta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cosTheta)^(3/2))
//
// Sampled exactly by inverting its CDF (pbrt-v4's SampleHenyeyGreenstein, in this convention);
// the weight p / pdf is 1.
#include "render/math/frame.h"
#include "render/math/vec.h"

namespace pt {

// Beyond this |g| the lobe is narrower than float resolves near its peak; clamped to it.
constexpr float kMaxHenyeyGreensteinG = 0.999f;

PT_HD float henyeyGreenstein(float cosTheta, float g) {
    g = clampf(g, -kMaxHenyeyGreensteinG, kMaxHenyeyGreensteinG);
    const float denom = 1.0f + g * g - 2.0f * g * cosTheta;
    return (1.0f - g * g) / (4.0f * kPi * denom * sqrtf(denom));
}

// The cosine of a scattering angle distributed as henyeyGreenstein(., g), from u in [0, 1).
PT_HD float sampleHenyeyGreensteinCosine(float g, float u) {
    g = clampf(g, -kMaxHenyeyGreensteinG, kMaxHenyeyGreensteinG);
    if (fabsf(g) < 1e-3f) return 2.0f * u - 1.0f;  // isotropic: the closed form divides by g
    const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u);
    return clampf((1.0f + g * g - s * s) / (2.0f * g), -1.0f, 1.0f);
}

struct PhaseSample {
    Vec3 direction;  // unit, the direction the light leaves along
    float pdf;       // solid-angle density, = the phase function's value
};

// A direction scattered from `travelling` (unit, the light's propagation direction).
PT_HD PhaseSample sampleHenyeyGreenstein(Vec3 travelling, float g, Vec2 u) {
    const float cosTheta = sampleHenyeyGreensteinCosine(g, u.x);
    const float sinTheta = sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * u.y;
    const Frame frame = Frame::fromNormal(travelling);
    const Vec3 local{sinTheta * cosf(phi), sinTheta * sinf(phi), cosTheta};
    return {normalize(frame.toWorld(local)), henyeyGreenstein(cosTheta, g)};
}

}  // namespace pt
