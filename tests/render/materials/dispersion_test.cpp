// KHR_materials_dispersion (dispersion.h): Cauchy's index through the Abbe number, the
// wavelength weights that keep a white path white on average, and the packing of a path's
// wavelength.
#include "render/materials/dispersion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pt {
namespace {

TEST(Dispersion, CauchyIndexHasTheAbbeNumberItWasGiven) {
    for (float ior : {1.33f, 1.5f, 2.42f}) {
        for (float dispersion : {0.2f, 1.0f, 3.0f}) {
            EXPECT_NEAR(dispersedIor(ior, dispersion, 587.56f), ior, 1e-5f);
            const float nF = dispersedIor(ior, dispersion, 486.13f),
                        nC = dispersedIor(ior, dispersion, 656.27f);
            // V_d = (n_d - 1) / (n_F - n_C) = 20 / dispersion.
            EXPECT_NEAR((ior - 1.0f) / (nF - nC), 20.0f / dispersion, 1e-2f * 20.0f / dispersion);
            EXPECT_GT(dispersedIor(ior, dispersion, 420.0f),
                      dispersedIor(ior, dispersion, 700.0f));  // blue bends more
        }
        EXPECT_EQ(dispersedIor(ior, 0.0f, 420.0f), ior) << "no dispersion: one index";
    }
    EXPECT_EQ(dispersedIor(1.0f, 1.0f, 420.0f), 1.0f) << "index-matched stays matched";
}

// Each channel's weight averages to 1 over the wavelengths a path can be given (else dispersive
// glass would tint white light), is never negative, and peaks where the eye's response does.
TEST(Dispersion, WavelengthWeightsAverageToWhite) {
    const int n = 70000;
    double sum[3] = {0, 0, 0};
    float peak[3] = {0, 0, 0}, peakAt[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
        const float nm = kVisibleMinNm + (i + 0.5f) * (kVisibleMaxNm - kVisibleMinNm) / n;
        const Vec3 w = wavelengthWeight(nm);
        for (int c = 0; c < 3; ++c) {
            ASSERT_GE(w[c], 0.0f) << nm;
            sum[c] += w[c] / n;
            if (w[c] > peak[c]) peak[c] = w[c], peakAt[c] = nm;
        }
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1.0, 2e-4) << "channel " << c;
    EXPECT_GT(peakAt[0], 580.0f);
    EXPECT_TRUE(peakAt[1] > 500.0f && peakAt[1] < 570.0f) << peakAt[1];
    EXPECT_LT(peakAt[2], 480.0f);
    for (float p : peak) EXPECT_LT(p, 6.5f) << "bounded weights";
}

TEST(Dispersion, PackedWavelengthsCoverTheRangeAndAreNeverNone) {
    EXPECT_EQ(packWavelength(0.0f), 1);
    EXPECT_EQ(packWavelength(0.99999994f), 65535);
    EXPECT_EQ(packWavelength(1.0f), 65535);
    EXPECT_NEAR(unpackWavelength(packWavelength(0.0f)), kVisibleMinNm, 0.01f);
    EXPECT_NEAR(unpackWavelength(packWavelength(0.99999994f)), kVisibleMaxNm, 0.01f);
    EXPECT_NEAR(unpackWavelength(packWavelength(0.5f)), 555.0f, 0.01f);
}

}  // namespace
}  // namespace pt
