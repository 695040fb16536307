#pragma once
// Warps from the unit square to the domains light transport samples, with their densities.
#include "render/math/vec.h"

namespace pt {

// Shirley-Chiu concentric map: square to unit disk, low distortion.
PT_HD Vec2 squareToConcentricDisk(Vec2 u) {
    const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
    float r, phi;
    if (fabsf(a) > fabsf(b)) {
        r = a;
        phi = (kPi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = (kPi / 2.0f) - (kPi / 4.0f) * (a / b);
    }
    return {r * cosf(phi), r * sinf(phi)};
}

// Cosine-weighted hemisphere about +Z; density cos(theta) / pi.
PT_HD Vec3 squareToCosineHemisphere(Vec2 u) {
    const Vec2 d = squareToConcentricDisk(u);
    const float z = sqrtf(fmaxf(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return {d.x, d.y, z};
}
PT_HD float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f; }

// Uniform barycentrics (b1, b2) on a triangle; the point is b0 p0 + b1 p1 + b2 p2 (Heitz,
// "A Low-Distortion Map Between Triangle and Square", 2019).
PT_HD Vec2 squareToTriangle(Vec2 u) {
    float b1, b2;
    if (u.y > u.x) {
        b1 = u.x * 0.5f;
        b2 = u.y - b1;
    } else {
        b2 = u.y * 0.5f;
        b1 = u.x - b2;
    }
    return {b1, b2};
}

// Power heuristic with beta = 2 (Veach 1997): weight of strategy `a` against `b`.
PT_HD float powerHeuristic(float pdfA, float pdfB) {
    const float a = pdfA * pdfA, b = pdfB * pdfB;
    if (a == 0.0f) return 0.0f;
    if (isInfinite(a)) return 1.0f;
    return a / (a + b);
}

}  // namespace pt
