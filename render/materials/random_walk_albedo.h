#pragma once
// From what an artist sets for subsurface scattering (a surface colour A and a mean free path d,
// per channel) to the coefficients of the homogeneous medium a random walk scatters in (issue
// 15): Chiang, Kutz and Burley, "Practical and Controllable Subsurface Scattering for Production
// Path Tracing" (SIGGRAPH 2016), whose fits Cycles' random-walk subsurface uses too.
//
//   single-scattering albedo  alpha = 1 - exp(-5.09406 A + 2.61188 A^2 - 4.31805 A^3)
//   extinction                sigma_t = 1 / (d s),   s = 1.9 - A + 3.5 (A - 0.8)^2
//
// so that a semi-infinite medium of isotropic scattering, lit from outside, reflects about A in
// all: the multiple-scattering albedo the artist picked (random_walk_albedo_test.cpp measures
// how close the fit comes), with light travelling about d before it leaves.
//
// The KHR_materials_volume_scatter proposal takes the extinction from the volume's attenuation
// and only inverts the albedo, by van de Hulst's relation in the form Kulla and Conty give
// ("Revisiting Physically Based Shading at Imageworks", SIGGRAPH 2017 course, slide 'albedo
// inversion'), with the anisotropy correction of the proposal:
//
//   s = 4.09712 + 4.20863 A - sqrt(9.59217 + 41.6808 A + 17.7126 A^2)
//   alpha = (1 - s^2) / (1 - g s^2)
#include "render/math/vec.h"

namespace pt {

// alpha(A) for A in [0, 1]; 0 and 1 map to 0 and 1.
PT_HD float randomWalkSingleScatterAlbedo(float surfaceAlbedo) {
    const float a = clampf(surfaceAlbedo, 0.0f, 1.0f);
    return 1.0f - expf(a * (-5.09406f + a * (2.61188f - a * 4.31805f)));
}

// sigma_t(A, d) per world unit; d > 0.
PT_HD float randomWalkExtinction(float surfaceAlbedo, float meanFreePath) {
    const float a = clampf(surfaceAlbedo, 0.0f, 1.0f);
    const float s = 1.9f - a + 3.5f * (a - 0.8f) * (a - 0.8f);
    return 1.0f / fmaxf(meanFreePath * s, 1e-30f);
}

// alpha(A, g) by van de Hulst's relation, for A in [0, 1] and |g| < 1.
PT_HD float vanDeHulstSingleScatterAlbedo(float multiScatterAlbedo, float g) {
    const float a = clampf(multiScatterAlbedo, 0.0f, 1.0f);
    const float s = fmaxf(4.09712f + 4.20863f * a - sqrtf(9.59217f + 41.6808f * a + 17.7126f * a * a), 0.0f);
    const float s2 = s * s;
    return clampf((1.0f - s2) / (1.0f - clampf(g, -0.999f, 0.999f) * s2), 0.0f, 1.0f);
}

}  // namespace pt
