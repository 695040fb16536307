// KHR_materials_iridescence (iridescence.h): the thin film's reflectance against an independent
// spectral computation (Airy's exact sum at normal incidence, integrated against the colour
// matching functions), its limits, and the BSDF that carries it.
#include "render/materials/iridescence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "chi_square.h"
#include "render/materials/bsdf.h"
#include "render/materials/dispersion.h"

namespace pt {
namespace {

// Reflectance of a film (index nFilm, thickness d nm) between air and a base of index nBase at
// normal incidence and wavelength lambda: Airy's sum of all orders, r = (r12 + r23 e^{i delta}) /
// (1 + r12 r23 e^{i delta}), delta = 4 pi nFilm d / lambda (Born and Wolf, 7.6.1).
double airyReflectance(double nFilm, double nBase, double d, double lambda) {
    const double r12 = (1.0 - nFilm) / (1.0 + nFilm), r23 = (nFilm - nBase) / (nFilm + nBase);
    const std::complex<double> phase = std::polar(1.0, 4.0 * M_PI * nFilm * d / lambda);
    return std::norm((r12 + r23 * phase) / (1.0 + r12 * r23 * phase));
}

// Its colour: the CIE 1931 responses (dispersion.h's fit) in linear Rec.709, negative lobes
// kept as the film model keeps them, each channel normalised so that a flat spectrum is white,
// as the model's own mean term is.
Vec3 spectralColour(double nFilm, double nBase, double d) {
    const int n = 3500;
    double sum[3] = {0, 0, 0}, area[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
        const double lambda = kVisibleMinNm + (i + 0.5) * (kVisibleMaxNm - kVisibleMinNm) / n;
        const Vec3 rgb = xyzToLinearRec709(cieColorMatching(float(lambda)));
        const double r = airyReflectance(nFilm, nBase, d, lambda);
        for (int c = 0; c < 3; ++c) sum[c] += rgb[c] * r, area[c] += rgb[c];
    }
    return {float(sum[0] / area[0]), float(sum[1] / area[1]), float(sum[2] / area[2])};
}

float f0Of(double n) { return float(((n - 1.0) / (n + 1.0)) * ((n - 1.0) / (n + 1.0))); }

// Soap (1.33) on glass (1.5) and a high-index film (2.0, titanium dioxide) on glass, across
// thicknesses where the colours run through the first orders: Belcour and Barla's closed form
// (two orders of Airy's sum, Gaussian fits to the eye's responses) stays within 0.03 of the
// exact spectrum (0.0248 at most, red under the 2.0 film, where the third order the sum leaves
// out is largest); a wrong phase or path difference is off by 0.1 and more.
TEST(ThinFilm, MatchesTheExactSpectrumAtNormalIncidence) {
    double worst = 0.0;
    for (double nFilm : {1.33, 2.0}) {
        for (double d : {50.0, 100.0, 150.0, 250.0, 400.0, 600.0}) {
            const Vec3 exact = spectralColour(nFilm, 1.5, d);
            const Vec3 model = thinFilmFresnel({1.0f, float(nFilm), float(d)}, Vec3(f0Of(1.5)), 1.0f);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(model[c], exact[c], 0.03)
                    << "film " << nFilm << " thickness " << d << " channel " << c;
                worst = std::max(worst, double(std::fabs(model[c] - exact[c])));
            }
        }
    }
    std::printf("thin film against the exact spectrum: largest difference %.4f\n", worst);
}

// A quarter-wave soap film on glass at 550 nm interferes destructively in green: green drops far
// below the bare glass's 4%, while a half-wave film reflects about what bare glass does.
TEST(ThinFilm, QuarterWaveFilmsCancelGreen) {
    const float quarter = float(550.0 / (4.0 * 1.33));
    const Vec3 r = thinFilmFresnel({1.0f, 1.33f, quarter}, Vec3(0.04f), 1.0f);
    EXPECT_LT(r.y, 0.02f) << r.x << " " << r.y << " " << r.z;
    const Vec3 thin = thinFilmFresnel({1.0f, 1.33f, 0.0f}, Vec3(0.04f), 1.0f);
    EXPECT_NEAR(thin.y, 0.04f, 0.01f) << "a vanishing film leaves the base";
}

TEST(ThinFilm, StaysInTheUnitRangeAndFiniteAtExtremes) {
    for (float ior : {1.0f, 1.0001f, 1.3f, 2.5f, 4.0f}) {
        for (float thickness : {0.0f, 0.01f, 1.0f, 300.0f, 1200.0f, 1e5f}) {
            for (float base : {0.0f, 0.04f, 0.5f, 0.99f, 1.0f}) {
                for (float c : {0.0f, 1e-6f, 0.3f, 1.0f}) {
                    const Vec3 r = thinFilmFresnel({1.0f, ior, thickness}, Vec3(base), c);
                    ASSERT_TRUE(isFinite(r)) << ior << " " << thickness << " " << base << " " << c;
                    EXPECT_GE(minComponent(r), 0.0f);
                    EXPECT_LE(maxComponent(r), 1.0f);
                }
            }
        }
    }
}

// An iridescent white material never gains energy in the white furnace, and weight 0 is the
// material without the film.
TEST(ThinFilm, IridescentMaterialsConserveEnergy) {
    test::Pcg32 rng(3);
    const Frame frame = Frame::fromNormal({0.0f, 0.0f, 1.0f});
    for (float metallic : {0.0f, 0.5f, 1.0f}) {
        for (float roughness : {0.0f, 0.3f, 1.0f}) {
            for (float filmIor : {1.2f, 2.0f, 3.0f}) {
                for (float thickness : {100.0f, 300.0f, 700.0f}) {
                    BsdfParams p{{1.0f, 1.0f, 1.0f}, metallic, 0.0f, 1.5f};
                    p.roughness = roughness;
                    p.iridescence = 1.0f;
                    p.iridescenceIor = filmIor;
                    p.iridescenceThickness = thickness;
                    for (float cosTheta : {1.0f, 0.5f, 0.1f}) {
                        const Vec3 wo{sqrtf(1.0f - cosTheta * cosTheta), 0.0f, cosTheta};
                        double sum = 0.0, sum2 = 0.0;
                        const int n = 20000;
                        for (int i = 0; i < n; ++i) {
                            const BsdfSample s =
                                sampleBsdf(p, frame, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
                            ASSERT_TRUE(isFinite(s.weight));
                            sum += maxComponent(s.weight);
                            sum2 += double(maxComponent(s.weight)) * maxComponent(s.weight);
                        }
                        const double mean = sum / n,
                                     standardError = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
                        EXPECT_LE(mean, 1.0 + 4.0 * standardError + 1e-3)
                            << metallic << " " << roughness << " " << filmIor << " " << thickness << " "
                            << cosTheta;
                    }
                }
            }
        }
    }
    BsdfParams plain{{0.6f, 0.3f, 0.2f}, 0.4f, 0.0f, 1.5f};
    plain.roughness = 0.4f;
    BsdfParams unfilmed = plain;
    unfilmed.iridescenceIor = 2.0f;
    unfilmed.iridescenceThickness = 300.0f;  // weight 0
    const Vec3 wo = normalize(Vec3{0.3f, 0.1f, 0.9f}), wi = normalize(Vec3{-0.2f, 0.3f, 0.8f});
    const Vec3 a = evalBsdf(plain, frame, wo, wi), b = evalBsdf(unfilmed, frame, wo, wi);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(a[c], b[c]);
}

// A film on glass (a soap bubble) is lossless: each channel's mean sample weight (refracted ones
// times eta^2) is 1 when smooth, at most 1 when rough, from either side; and the film colours
// what the glass reflects, where glass without it reflects grey.
TEST(ThinFilm, FilmedGlassKeepsEachChannelsEnergy) {
    test::Pcg32 rng(8);
    const Frame frame = Frame::fromNormal({0.0f, 0.0f, 1.0f});
    for (float roughness : {0.0f, 0.3f}) {
        BsdfParams bubble{{1.0f, 1.0f, 1.0f}, 0.0f, 1.0f, 1.5f};
        bubble.roughness = roughness;
        bubble.iridescence = 1.0f;
        bubble.iridescenceIor = 1.33f;
        bubble.iridescenceThickness = 300.0f;
        for (float cosTheta : {1.0f, 0.6f, 0.2f}) {
            for (bool inside : {false, true}) {
                const Vec3 wo{sqrtf(1.0f - cosTheta * cosTheta), 0.0f, inside ? -cosTheta : cosTheta};
                const float etap = inside ? 1.0f / 1.5f : 1.5f;
                const int n = 40000;
                double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0}, reflected[3] = {0, 0, 0};
                for (int i = 0; i < n; ++i) {
                    const BsdfSample s =
                        sampleBsdf(bubble, frame, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
                    ASSERT_TRUE(isFinite(s.weight));
                    for (int c = 0; c < 3; ++c) {
                        const double w = s.weight[c] * (s.refracted ? double(etap) * etap : 1.0);
                        sum[c] += w;
                        sum2[c] += w * w;
                        if (!s.transmitted) reflected[c] += w;
                    }
                }
                for (int c = 0; c < 3; ++c) {
                    const double mean = sum[c] / n,
                                 se = std::sqrt(std::max(0.0, sum2[c] / n - mean * mean) / n);
                    EXPECT_LE(mean, 1.0 + 4.0 * se + 1e-3) << roughness << " " << cosTheta << " " << inside;
                    if (roughness == 0.0f) {
                        EXPECT_NEAR(mean, 1.0, 4.0 * se + 1e-3) << cosTheta << " " << inside;
                    }
                }
                if (roughness == 0.0f && !inside && cosTheta == 1.0f) {
                    const double r = reflected[0] / n, b = reflected[2] / n;
                    EXPECT_GT(std::fabs(r - b), 0.005) << "a 300 nm soap film is coloured: " << r << " " << b;
                }
            }
        }
    }
}

}  // namespace
}  // namespace pt
