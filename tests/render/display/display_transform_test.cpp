// The built-in display operators (AgX against an independent double-precision transcription
// of the published GLSL), operator names, and the 8-bit dither.
#include "render/display/display_transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace pt {
namespace {

TEST(DisplayTransform, ToneMapperNamesRoundTrip) {
    std::set<std::string> names;
    for (uint32_t i = 0; i < uint32_t(ToneMapper::Count); ++i) {
        const ToneMapper op = ToneMapper(i);
        ToneMapper parsed = ToneMapper::Count;
        ASSERT_TRUE(parseToneMapper(toneMapperName(op), parsed)) << toneMapperName(op);
        EXPECT_EQ(parsed, op);
        names.insert(toneMapperName(op));
    }
    EXPECT_EQ(names, (std::set<std::string>{"standard", "reinhard", "aces-fitted", "agx"}));
    ToneMapper untouched = ToneMapper::Reinhard;
    EXPECT_FALSE(parseToneMapper("filmic", untouched));
    EXPECT_EQ(untouched, ToneMapper::Reinhard);
}

// three.js's AgXToneMapping (after Filament and Benjamin Wrensch) as published: GLSL mat3
// constructors take columns, so M * v sums column j times v[j]. Doubles throughout.
void agxReference(const double in[3], double out[3]) {
    const double toRec2020[3][3] = {
        {0.6274, 0.0691, 0.0164}, {0.3293, 0.9195, 0.0880}, {0.0433, 0.0113, 0.8956}};
    const double fromRec2020[3][3] = {
        {1.6605, -0.1246, -0.0182}, {-0.5876, 1.1329, -0.1006}, {-0.0728, -0.0083, 1.1187}};
    const double inset[3][3] = {{0.856627153315983, 0.137318972929847, 0.11189821299995},
                                {0.0951212405381588, 0.761241990602591, 0.0767994186031903},
                                {0.0482516061458583, 0.101439036467562, 0.811302368396859}};
    const double outset[3][3] = {{1.1271005818144368, -0.1413297634984383, -0.14132976349843826},
                                 {-0.11060664309660323, 1.157823702216272, -0.11060664309660294},
                                 {-0.016493938717834573, -0.016493938717834257, 1.2519364065950405}};
    auto mul = [](const double(&columns)[3][3], const double v[3], double r[3]) {
        for (int i = 0; i < 3; ++i) r[i] = columns[0][i] * v[0] + columns[1][i] * v[1] + columns[2][i] * v[2];
    };
    double a[3], b[3];
    mul(toRec2020, in, a);
    mul(inset, a, b);
    for (double& c : b) {
        const double x =
            std::clamp((std::log2(std::max(c, 1e-10)) + 12.47393) / (4.026069 + 12.47393), 0.0, 1.0);
        const double x2 = x * x, x4 = x2 * x2;
        c = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x -
            0.00232;
    }
    mul(outset, b, a);
    for (double& c : a) c = std::pow(std::max(c, 0.0), 2.2);
    mul(fromRec2020, a, out);
    for (int i = 0; i < 3; ++i) out[i] = std::clamp(out[i], 0.0, 1.0);
}

TEST(DisplayTransform, AgxMatchesThePublishedShader) {
    // three.js rounds its Rec.709 <-> Rec.2020 matrices to 4 digits; ours come from the
    // primaries. That and float arithmetic stay far below 1e-3 of display light.
    const float colours[][3] = {{0.18f, 0.18f, 0.18f},
                                {1, 1, 1},
                                {0.01f, 0.01f, 0.01f},
                                {16, 16, 16},
                                {1, 0, 0},
                                {0, 1, 0},
                                {0, 0, 1},
                                {0.8f, 0.3f, 0.05f},
                                {0.05f, 0.4f, 2.0f},
                                {5, 0.5f, 0.1f},
                                {0, 0, 0}};
    for (const auto& c : colours) {
        const double in[3] = {c[0], c[1], c[2]};
        double expected[3];
        agxReference(in, expected);
        const Vec3 got = agxToneMap(Vec3(c[0], c[1], c[2]));
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(got[i], expected[i], 1e-3) << c[0] << " " << c[1] << " " << c[2] << " channel " << i;
        }
    }
}

TEST(DisplayTransform, AgxKeepsGreyNeutralMonotonicAndBounded) {
    float previous = -1.0f;
    for (int stop = -14; stop <= 10; ++stop) {
        const Vec3 out = agxToneMap(Vec3(0.18f * std::exp2(float(stop))));
        EXPECT_NEAR(out.x, out.y, 1e-4f) << stop;
        EXPECT_NEAR(out.y, out.z, 1e-4f) << stop;
        EXPECT_GE(out.x, previous) << stop;
        EXPECT_LE(out.x, 1.0f);
        previous = out.x;
    }
    EXPECT_LT(agxToneMap(Vec3(0.0f)).x, 1e-4f);
    // Middle grey lands near the middle of the sRGB code range (three.js: 0.5005).
    EXPECT_NEAR(linearToSrgb(agxToneMap(Vec3(0.18f)).x), 0.5005f, 0.002f);
}

TEST(Dither, OffsetIsTriangularInTheOpenUnitIntervalAndDeterministic) {
    double sum = 0.0, sumSquares = 0.0;
    uint32_t inner = 0;  // |offset| < 0.5: a triangular PDF puts 3/4 of its mass there
    const uint32_t n = 512;
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x < n; ++x) {
            const float d = ditherOffset(x, y);
            ASSERT_GT(d, -1.0f);
            ASSERT_LT(d, 1.0f);
            ASSERT_EQ(d, ditherOffset(x, y));
            sum += d;
            sumSquares += double(d) * d;
            inner += std::fabs(d) < 0.5f ? 1 : 0;
        }
    }
    const double count = double(n) * n;
    EXPECT_NEAR(sum / count, 0.0, 0.005);
    EXPECT_NEAR(sumSquares / count, 1.0 / 6.0, 0.005);  // variance of the triangle on (-1, 1)
    EXPECT_NEAR(inner / count, 0.75, 0.005);
    EXPECT_NE(ditherOffset(0, 0), ditherOffset(1, 0));
    EXPECT_NE(ditherOffset(0, 0), ditherOffset(0, 1));
}

TEST(Dither, FlatFieldMeanIsTheUnquantisedValue) {
    for (const float v : {0.3f, 0.1234f, 0.5f, 0.0021f, 0.9961f}) {
        const double exact = double(v) * 255.0;
        double sum = 0.0;
        bool differs = false;
        const uint32_t n = 256;
        for (uint32_t y = 0; y < n; ++y) {
            for (uint32_t x = 0; x < n; ++x) {
                const uint8_t q = quantize8(v, ditherOffset(x, y));
                sum += q;
                differs = differs || q != quantize8(v, 0.0f);
            }
        }
        EXPECT_NEAR(sum / (n * n), exact, 0.1) << v;
        EXPECT_TRUE(differs) << v;
    }
    // Without dithering: plain rounding, clamped.
    EXPECT_EQ(quantize8(0.3f, 0.0f), 77);  // 76.5 rounds up
    EXPECT_EQ(quantize8(-0.2f, 0.0f), 0);
    EXPECT_EQ(quantize8(1.5f, 0.0f), 255);
    EXPECT_EQ(quantize8(std::nanf(""), 0.0f), 0);
}

TEST(Dither, EncodeDisplay8DithersByPixelPositionOnlyWhenAsked) {
    const uint32_t width = 64, height = 32;
    std::vector<float> rgba(size_t(width) * height * 4, 0.05f);  // sRGB 0.2479: 63.2 LSB
    DisplaySettings plain;
    plain.dither = false;
    const std::vector<uint8_t> flat = encodeDisplay8(rgba, width, plain);
    for (uint8_t v : flat) ASSERT_EQ(v, 63);
    const DisplaySettings dithered;  // on by default
    ASSERT_TRUE(dithered.dither);
    const std::vector<uint8_t> a = encodeDisplay8(rgba, width, dithered);
    EXPECT_EQ(a, encodeDisplay8(rgba, width, dithered)) << "deterministic";
    EXPECT_NE(a, flat);
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); i += 3) {
        const float offset = ditherOffset(uint32_t((i / 3) % width), uint32_t((i / 3) / width));
        ASSERT_EQ(a[i], quantize8(linearToSrgb(0.05f), offset)) << "pixel " << i / 3;
        sum += a[i];
    }
    EXPECT_NEAR(sum / (a.size() / 3), linearToSrgb(0.05f) * 255.0f, 0.1);
    // Non-finite pixels display as 0 whatever the dither.
    rgba[0] = std::nanf("");
    rgba[1] = INFINITY;
    plain.toneMapper = ToneMapper::AgX;
    const std::vector<uint8_t> withNan = encodeDisplay8(rgba, width, plain);
    EXPECT_EQ(withNan[0], quantize8(linearToSrgb(agxToneMap(Vec3(0.0f, 0.0f, 0.05f)).x), 0.0f));
}

}  // namespace
}  // namespace pt
