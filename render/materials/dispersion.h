#pragma once
// KHR_materials_dispersion: an index of refraction that depends on the wavelength, rendered by
// giving a path one wavelength at the first dispersive surface it meets ("hero" wavelength
// sampling with a single wavelength; Wilkie et al. 2014 carry four, which an RGB renderer
// cannot use). From there on the path refracts with that wavelength's index, and its RGB
// throughput is weighted by the response of each channel to it:
//
//   channel c of the pixel = integral of s_c(lambda) L(lambda) d lambda,  integral of s_c = 1,
//
// with s_c the CIE 1931 colour matching functions (the analytic multi-lobe fit of Wyman, Sloan
// and Shirley, JCGT 2013) taken to linear Rec.709, negative lobes clipped, each normalised to
// unit area over 380-730 nm. A scene without dispersion is unchanged in expectation (each
// channel's weights average to one), paths that never meet a dispersive surface are unchanged
// exactly, and dispersion spreads white light into a continuous spectrum rather than three
// images (the RGB approximation of Khronos' Sample Viewer refracts three indices, one a channel).
//
// The wavelength is drawn uniformly over the range: weights stay below 6.1, and the CDF of the
// responses has no closed form to invert.
//
// The index follows Cauchy's equation n = A + B / lambda^2 through the material's ior at the
// d line with the Abbe number V_d = 20 / dispersion, as the extension specifies:
//   B = (n_d - 1) / (V_d (1/lambda_F^2 - 1/lambda_C^2)),  A = n_d - B / lambda_d^2.
#include "render/math/cie_xyz.h"

namespace pt {

constexpr float kVisibleMinNm = 380.0f;
constexpr float kVisibleMaxNm = 730.0f;

PT_HD float dispersedIor(float ior, float dispersion, float wavelengthNm) {
    if (!(dispersion > 0.0f) || !(ior > 1.0f)) return ior;
    constexpr float kD = 587.56f, kF = 486.13f, kC = 656.27f;  // Fraunhofer lines, nm
    const float abbe = 20.0f / dispersion;
    const float b = (ior - 1.0f) / (abbe * (1.0f / (kF * kF) - 1.0f / (kC * kC)));
    return fmaxf(ior + b * (1.0f / (wavelengthNm * wavelengthNm) - 1.0f / (kD * kD)), 1.0f);
}

namespace dispersion_detail {

// Each channel's integral over 380-730 nm of the clipped response (numerical, 350 000 steps).
constexpr float kChannelArea[3] = {176.17727f, 115.38126f, 109.31846f};

}  // namespace dispersion_detail

// s_c(lambda) / pdf(lambda) for a wavelength drawn uniformly over the visible range: the factor a
// path's throughput takes when it is given that wavelength. Its mean over the range is 1 in
// every channel.
PT_HD Vec3 wavelengthWeight(float nm) {
    const Vec3 rgb = xyzToLinearRec709(cieColorMatching(nm));
    constexpr float kRange = kVisibleMaxNm - kVisibleMinNm;
    using dispersion_detail::kChannelArea;
    return vmax(rgb, Vec3(0.0f)) *
           Vec3(kRange / kChannelArea[0], kRange / kChannelArea[1], kRange / kChannelArea[2]);
}

// A path's wavelength packed in 16 bits (PathState::wavelength): 0 is none yet, 1..65535 the
// centres of equal bins over the visible range.
PT_HD uint16_t packWavelength(float u) {
    const float bin = fminf(fmaxf(u, 0.0f) * 65535.0f, 65534.0f);
    return uint16_t(1u + uint32_t(bin));
}
PT_HD float unpackWavelength(uint16_t packed) {
    return kVisibleMinNm + (float(packed) - 0.5f) * ((kVisibleMaxNm - kVisibleMinNm) / 65535.0f);
}

}  // namespace pt
