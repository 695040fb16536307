#pragma once
// CIE 1931 colorimetry: the colour matching functions and XYZ to linear Rec.709 (the renderer's
// working space, D65), for the spectral effects of an RGB renderer (dispersion.h, iridescence.h).
#include "render/math/vec.h"

namespace pt {

PT_HD Vec3 xyzToLinearRec709(Vec3 xyz) {
    return {3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
            -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
            0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z};
}

namespace cie_detail {

// A Gaussian with different widths left and right of its mean (Wyman et al. 2013, eq. 1).
PT_HD float piecewiseGaussian(float x, float mean, float sigmaLeft, float sigmaRight) {
    const float t = (x - mean) / (x < mean ? sigmaLeft : sigmaRight);
    return expf(-0.5f * t * t);
}

}  // namespace cie_detail

// x-bar, y-bar, z-bar at `nm` nanometres: the multi-lobe fit of Wyman, Sloan and Shirley,
// "Simple Analytic Approximations to the CIE XYZ Color Matching Functions" (JCGT 2013).
PT_HD Vec3 cieColorMatching(float nm) {
    using cie_detail::piecewiseGaussian;
    return {1.056f * piecewiseGaussian(nm, 599.8f, 37.9f, 31.0f) +
                0.362f * piecewiseGaussian(nm, 442.0f, 16.0f, 26.7f) -
                0.065f * piecewiseGaussian(nm, 501.1f, 20.4f, 26.2f),
            0.821f * piecewiseGaussian(nm, 568.8f, 46.9f, 40.5f) +
                0.286f * piecewiseGaussian(nm, 530.9f, 16.3f, 31.1f),
            1.217f * piecewiseGaussian(nm, 437.0f, 11.8f, 36.0f) +
                0.681f * piecewiseGaussian(nm, 459.0f, 26.0f, 13.8f)};
}

}  // namespace pt
