// The glTF BSDF (bsdf.h): the scene presets behave exactly as before, sample weights agree with
// eval / pdf and with closed forms, reflection is reciprocal, no material gains energy in a white
// furnace at any angle or roughness, and stiff inputs never produce NaN or Inf.
#include "render/materials/bsdf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "chi_square.h"

namespace pt {
namespace {

using test::Pcg32;

const Frame kIdentity = Frame::fromNormal({0.0f, 0.0f, 1.0f});

Vec3 directionAt(float cosTheta) { return {sqrtf(fmaxf(0.0f, 1.0f - cosTheta * cosTheta)), 0.0f, cosTheta}; }

BsdfParams makeParams(Vec3 base, float metallic, float transmission, float ior, float roughness) {
    BsdfParams p{base, metallic, transmission, ior};
    p.roughness = roughness;
    return p;
}

Vec3 randomDirection(Pcg32& rng, bool upper) {
    const float z = rng.uniform(), phi = 2.0f * kPi * rng.uniform();
    const float r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
    return {r * cosf(phi), r * sinf(phi), upper ? z : -z};
}

float relativeError(float a, float b) { return fabsf(a - b) / fmaxf(fmaxf(fabsf(a), fabsf(b)), 1e-30f); }

// eta_t / eta_i for a refraction leaving wo's side.
float relativeEtaFor(const BsdfParams& p, Vec3 wo) { return wo.z > 0.0f ? p.ior : 1.0f / p.ior; }

TEST(Fresnel, DielectricMatchesKnownValues) {
    EXPECT_NEAR(fresnelDielectric(1.0f, 1.5f), 0.04f, 1e-6f);     // ((1.5-1)/(1.5+1))^2
    EXPECT_NEAR(fresnelDielectric(0.3f, 1.0f), 0.0f, 1e-7f);      // index-matched: no interface
    EXPECT_FLOAT_EQ(fresnelDielectric(0.1f, 1.0f / 1.5f), 1.0f);  // total internal reflection
    EXPECT_NEAR(fresnelDielectric(1e-6f, 1.5f), 1.0f, 1e-4f);     // grazing
    EXPECT_NEAR(fresnelDielectric(1.0f, 4.0f), 0.36f, 1e-6f);
    EXPECT_NEAR(dielectricF0(1.5f), 0.04f, 1e-7f);
    const Vec3 f = fresnelSchlick(Vec3(0.04f), Vec3(0.5f), 0.0f);  // KHR_materials_specular's F90
    EXPECT_FLOAT_EQ(f.x, 0.5f);
}

// --- The scene presets ----------------------------------------------------------------------

// "diffuse" = metallic 0 + specular 0: exactly Lambertian, whatever the roughness.
TEST(BsdfPresets, DiffuseIsExactlyLambertian) {
    for (float roughness : {0.0f, 0.5f, 1.0f}) {
        BsdfParams p = makeParams({0.5f, 0.25f, 1.0f}, 0.0f, 0.0f, 1.5f, roughness);
        p.specular = 0.0f;
        EXPECT_TRUE(hasNonDeltaLobes(p));
        Pcg32 rng(3);
        for (int i = 0; i < 256; ++i) {
            const Vec3 wo = randomDirection(rng, true);
            const BsdfSample s = sampleBsdf(p, kIdentity, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
            ASSERT_FALSE(s.delta);
            ASSERT_FALSE(s.transmitted);
            ASSERT_GT(s.pdf, 0.0f);
            EXPECT_EQ(s.weight, p.baseColor);
            EXPECT_FLOAT_EQ(s.pdf, s.wi.z * kInvPi);
            const Vec3 f = evalBsdf(p, kIdentity, wo, s.wi);
            EXPECT_EQ(f, p.baseColor * (kInvPi * s.wi.z));
            EXPECT_EQ(pdfBsdf(p, kIdentity, wo, s.wi), cosineHemispherePdf(s.wi.z));
        }
    }
}

// "mirror" = metallic 1, roughness 0: a perfect mirror with Schlick's Fresnel of baseColor.
TEST(BsdfPresets, MirrorIsAPerfectSchlickConductor) {
    const BsdfParams mirror = makeParams({0.9f, 0.6f, 0.3f}, 1.0f, 0.0f, 1.5f, 0.0f);
    EXPECT_FALSE(hasNonDeltaLobes(mirror));
    EXPECT_FALSE(isTransmissive(mirror));
    for (float cosTheta : {1.0f, 0.5f, 0.1f, 1e-6f}) {
        const Vec3 wo = directionAt(cosTheta);
        const BsdfSample s = sampleBsdf(mirror, kIdentity, wo, 0.3f, {0.5f, 0.5f});
        EXPECT_TRUE(s.delta);
        EXPECT_FALSE(s.transmitted);
        EXPECT_EQ(s.wi, Vec3(-wo.x, -wo.y, wo.z));
        const Vec3 expected = fresnelSchlick(mirror.baseColor, cosTheta);
        EXPECT_FLOAT_EQ(s.weight.x, expected.x);
        EXPECT_FLOAT_EQ(s.weight.z, expected.z);
        EXPECT_EQ(evalBsdf(mirror, kIdentity, wo, s.wi), Vec3(0.0f));
        EXPECT_EQ(pdfBsdf(mirror, kIdentity, wo, s.wi), 0.0f);
    }
}

// "glass" = transmission 1, roughness 0, ior 1.5: a smooth dielectric. A white one loses no
// energy: reflection and refraction split by Fresnel, each weight 1 (refraction's 1/eta^2 is
// radiance compression, undone on exit).
TEST(BsdfPresets, SmoothGlassSplitsByFresnelAndConservesEnergy) {
    for (float ior : {1.0f, 1.0001f, 1.5f, 2.42f, 4.0f}) {
        for (float cosTheta : {1.0f, 0.7f, 0.2f, 1e-3f}) {
            for (bool inside : {false, true}) {
                const BsdfParams p = makeParams({1, 1, 1}, 0.0f, 1.0f, ior, 0.0f);
                const Vec3 wo =
                    inside ? Vec3(directionAt(cosTheta).x, 0.0f, -cosTheta) : directionAt(cosTheta);
                const float etap = relativeEtaFor(p, wo);
                const int kN = 20000;
                int reflected = 0;
                double energy = 0;
                for (int i = 0; i < kN; ++i) {
                    const BsdfSample s = sampleBsdf(p, kIdentity, wo, (float(i) + 0.5f) / kN, {0.5f, 0.5f});
                    ASSERT_TRUE(s.delta);
                    ASSERT_TRUE(isFinite(s.weight));
                    ASSERT_NEAR(length(s.wi), 1.0f, 1e-5f);
                    if (s.transmitted) {
                        EXPECT_LT(s.wi.z * wo.z, 0.0f);
                        energy += s.weight.x * etap * etap;
                    } else {
                        EXPECT_NEAR(s.wi.z, wo.z, 1e-5f);
                        EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
                        energy += s.weight.x;
                        ++reflected;
                    }
                }
                const float fresnel = fresnelDielectric(cosTheta, etap);
                EXPECT_NEAR(double(reflected) / kN, fresnel, 2e-4) << "ior " << ior << " cos " << cosTheta;
                EXPECT_NEAR(energy / kN, 1.0, 1e-5);
            }
        }
    }
}

TEST(BsdfPresets, GlassRefractionIsTintedByBaseColor) {
    const BsdfParams p = makeParams({0.8f, 0.8f, 0.8f}, 0.0f, 1.0f, 1.5f, 0.0f);  // the preset
    const BsdfSample s = sampleBsdf(p, kIdentity, directionAt(1.0f), 0.999f, {0.5f, 0.5f});
    ASSERT_TRUE(s.transmitted);
    EXPECT_NEAR(s.weight.x, 0.8f / (1.5f * 1.5f), 1e-6f);
}

TEST(Bsdf, IndexMatchedGlassPassesStraightThroughAtAnyRoughness) {
    for (float roughness : {0.0f, 0.5f, 1.0f}) {
        const BsdfParams p = makeParams({1, 1, 1}, 0.0f, 1.0f, 1.0f, roughness);
        EXPECT_FALSE(hasNonDeltaLobes(p));
        const Frame frame = Frame::fromNormal(normalize(Vec3{0.3f, -0.2f, 0.9f}));
        const Vec3 wo = normalize(Vec3{0.5f, 0.1f, 0.7f});
        for (float u : {0.0f, 0.5f, 0.999f}) {
            const BsdfSample s = sampleBsdf(p, frame, wo, u, {0.5f, 0.5f});
            EXPECT_TRUE(s.transmitted);
            EXPECT_TRUE(s.delta);
            EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
            EXPECT_NEAR(s.wi.x, -wo.x, 1e-5f);
            EXPECT_NEAR(s.wi.y, -wo.y, 1e-5f);
            EXPECT_NEAR(s.wi.z, -wo.z, 1e-5f);
        }
    }
}

TEST(Bsdf, GlassInsideTotallyReflectsBeyondTheCriticalAngle) {
    const BsdfParams p = makeParams({1, 1, 1}, 0.0f, 1.0f, 1.5f, 0.0f);
    const Vec3 wo = {0.9f, 0.0f, -sqrtf(1.0f - 0.81f)};  // inside, 64 degrees from the normal
    for (float u : {0.0f, 0.5f, 0.999f}) {
        const BsdfSample s = sampleBsdf(p, kIdentity, wo, u, {0.5f, 0.5f});
        EXPECT_FALSE(s.transmitted);
        EXPECT_LT(s.wi.z, 0.0f);  // stays inside
        EXPECT_NEAR(s.weight.x, 1.0f, 1e-6f);
    }
}

TEST(Bsdf, LobeClassification) {
    EXPECT_TRUE(hasNonDeltaLobes(makeParams({1, 1, 1}, 0.0f, 1.0f, 1.5f, 0.3f)));    // rough glass
    EXPECT_FALSE(hasNonDeltaLobes(makeParams({1, 1, 1}, 0.0f, 1.0f, 1.5f, 1e-4f)));  // smooth glass
    EXPECT_TRUE(hasNonDeltaLobes(makeParams({1, 1, 1}, 1.0f, 0.0f, 1.5f, 0.3f)));    // rough metal
    BsdfParams coatedMirror = makeParams({1, 1, 1}, 1.0f, 0.0f, 1.5f, 0.0f);
    coatedMirror.clearcoat = 1.0f;
    EXPECT_FALSE(hasNonDeltaLobes(coatedMirror));
    coatedMirror.clearcoatRoughness = 0.3f;
    EXPECT_TRUE(hasNonDeltaLobes(coatedMirror));
    EXPECT_TRUE(isTransmissive(makeParams({1, 1, 1}, 0.5f, 0.5f, 1.5f, 0.3f)));
    EXPECT_FALSE(isTransmissive(makeParams({1, 1, 1}, 1.0f, 1.0f, 1.5f, 0.3f)));
}

// --- Weights, pdfs and reciprocity ----------------------------------------------------------

std::vector<BsdfParams> mixedMaterials(float roughness) {
    std::vector<BsdfParams> out;
    out.push_back(makeParams({0.9f, 0.6f, 0.3f}, 1.0f, 0.0f, 1.5f, roughness));  // metal
    out.push_back(makeParams({0.5f, 0.7f, 0.2f}, 0.0f, 0.0f, 1.5f, roughness));  // plastic
    BsdfParams tinted = makeParams({0.2f, 0.3f, 0.9f}, 0.0f, 0.0f, 1.8f, roughness);
    tinted.specular = 0.6f;
    tinted.specularColor = {1.0f, 0.5f, 2.0f};
    out.push_back(tinted);
    out.push_back(makeParams({0.9f, 0.9f, 0.7f}, 0.0f, 1.0f, 1.5f, roughness));  // glass
    out.push_back(makeParams({0.7f, 0.5f, 0.3f}, 0.3f, 0.4f, 2.0f, roughness));  // a bit of everything
    return out;
}

// For non-delta samples the weight is f |cos| / pdf of the whole mixture, and the pdf is
// pdfBsdf's, in any frame (to float precision: a rotated narrow lobe moves by an ulp of
// direction, which changes its density by up to ~1e-2 relative at roughness 0.05).
TEST(Bsdf, SampleWeightIsEvalOverPdfInAnyFrame) {
    Pcg32 rng(11);
    int checked = 0;
    for (bool rotated : {false, true}) {
        const float tolerance = rotated ? 2e-2f : 1e-5f;
        for (float roughness : {0.05f, 0.3f, 1.0f}) {
            for (BsdfParams p : mixedMaterials(roughness)) {
                p.clearcoat = 0.5f;
                p.clearcoatRoughness = 0.2f;
                for (int i = 0; i < 400; ++i) {
                    const Frame frame =
                        rotated ? Frame::fromNormal(randomDirection(rng, rng.uniform() < 0.5f)) : kIdentity;
                    const Vec3 wo =
                        frame.toWorld(randomDirection(rng, p.transmission == 0.0f || rng.uniform() < 0.5f));
                    const BsdfSample s =
                        sampleBsdf(p, frame, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
                    if (s.delta || isBlack(s.weight)) continue;
                    const float pdf = pdfBsdf(p, frame, wo, s.wi);
                    const Vec3 f = evalBsdf(p, frame, wo, s.wi);
                    ASSERT_GT(pdf, 0.0f);
                    EXPECT_LT(relativeError(s.pdf, pdf), tolerance) << roughness;
                    for (int c = 0; c < 3; ++c)
                        EXPECT_LT(relativeError(s.weight[c], f[c] / pdf), tolerance) << roughness;
                    EXPECT_EQ(s.transmitted, dot(s.wi, frame.normal) * dot(wo, frame.normal) < 0.0f);
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 8000);
}

// The sheen lobe (KHR_materials_sheen), under a coat and over plastic, and over diffuse
// transmission: the sample weight is eval / pdf and the pdf is pdfBsdf's, in reflection.
TEST(Bsdf, SheenSampleWeightIsEvalOverPdf) {
    Pcg32 rng(23);
    int sheenSamples = 0;
    for (float sheenRoughness : {0.0f, 0.2f, 0.6f, 1.0f}) {
        BsdfParams p = makeParams({0.4f, 0.2f, 0.1f}, 0.0f, 0.0f, 1.5f, 0.4f);
        p.sheenColor = {0.9f, 0.7f, 1.0f};
        p.sheenRoughness = sheenRoughness;
        p.clearcoat = 0.3f;
        p.clearcoatRoughness = 0.3f;
        p.diffuseTransmission = 0.3f;
        for (int i = 0; i < 600; ++i) {
            const Vec3 wo = randomDirection(rng, true);
            const BsdfSample s = sampleBsdf(p, kIdentity, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
            if (s.delta || isBlack(s.weight)) continue;
            const float pdf = pdfBsdf(p, kIdentity, wo, s.wi);
            const Vec3 f = evalBsdf(p, kIdentity, wo, s.wi);
            ASSERT_GT(pdf, 0.0f);
            EXPECT_LT(relativeError(s.pdf, pdf), 1e-5f);
            for (int c = 0; c < 3; ++c) EXPECT_LT(relativeError(s.weight[c], f[c] / pdf), 1e-4f);
            sheenSamples += s.wi.z > 0.0f ? 1 : 0;
        }
    }
    EXPECT_GT(sheenSamples, 1000);
}

// Independent closed forms (double precision) of the visible-normal weights: F G2 / G1 for the
// conductor, G2 / G1 (over eta^2 when refracted) for a white dielectric.
double smithLambda(test::DVec3 w, double alpha) {
    const double t2 = (w.x * w.x + w.y * w.y) / (w.z * w.z);
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * t2) - 1.0);
}

TEST(Bsdf, SampleWeightsMatchTheirClosedForms) {
    Pcg32 rng(5);
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
        const double alpha = double(roughness) * roughness;
        const BsdfParams metal = makeParams({0.9f, 0.6f, 0.3f}, 1.0f, 0.0f, 1.5f, roughness);
        const BsdfParams glass = makeParams({1, 1, 1}, 0.0f, 1.0f, 1.5f, roughness);
        for (int i = 0; i < 300; ++i) {
            const Vec3 wo = randomDirection(rng, true);
            const BsdfSample s =
                sampleBsdf(metal, kIdentity, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
            if (isBlack(s.weight)) continue;
            const test::DVec3 o = test::toDouble(wo), w = test::toDouble(s.wi);
            const test::DVec3 h = test::normalized(o + w);
            const double g2OverG1 =
                (1.0 + smithLambda(o, alpha)) / (1.0 + smithLambda(o, alpha) + smithLambda(w, alpha));
            const double m = 1.0 - test::dot(o, h), m5 = m * m * m * m * m;
            EXPECT_NEAR(s.weight.x, (0.9 + 0.1 * m5) * g2OverG1, 2e-4);
            EXPECT_NEAR(s.weight.z, (0.3 + 0.7 * m5) * g2OverG1, 2e-4);
        }
        for (int i = 0; i < 300; ++i) {
            const Vec3 wo = randomDirection(rng, rng.uniform() < 0.5f);
            const BsdfSample s =
                sampleBsdf(glass, kIdentity, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
            if (isBlack(s.weight)) continue;
            const test::DVec3 o = test::toDouble(wo), w = test::toDouble(s.wi);
            const double g2OverG1 =
                (1.0 + smithLambda(o, alpha)) / (1.0 + smithLambda(o, alpha) + smithLambda(w, alpha));
            const float etap = relativeEtaFor(glass, wo);
            const double expected = s.transmitted ? g2OverG1 / (double(etap) * etap) : g2OverG1;
            EXPECT_NEAR(s.weight.x, expected, 2e-4 * expected + 1e-6) << s.transmitted;
        }
    }
}

// f(wo, wi) = f(wi, wo) for reflection (the clearcoat mix, weighted by N.V as the glTF
// extension specifies, is the one non-reciprocal part and is left out).
TEST(Bsdf, ReflectionIsReciprocal) {
    Pcg32 rng(17);
    int checked = 0;
    for (float roughness : {0.05f, 0.2f, 0.6f, 1.0f}) {
        for (const BsdfParams& p : mixedMaterials(roughness)) {
            for (int i = 0; i < 300; ++i) {
                const bool upper = p.transmission == 0.0f || rng.uniform() < 0.5f;
                const Vec3 a = randomDirection(rng, upper), b = randomDirection(rng, upper);
                const Vec3 fab = evalBsdf(p, kIdentity, a, b) / fabsf(b.z);
                const Vec3 fba = evalBsdf(p, kIdentity, b, a) / fabsf(a.z);
                for (int c = 0; c < 3; ++c) {
                    if (fab[c] < 1e-6f && fba[c] < 1e-6f) continue;
                    EXPECT_LT(relativeError(fab[c], fba[c]), 2e-3f) << "roughness " << roughness;
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 10000);
}

// --- Energy: the white furnace ----------------------------------------------------------------

struct EnergyEstimate {
    double mean = 0.0, standardError = 0.0, maxWeight = 0.0;
    bool finite = true;
};

// Mean of the sample weights (refracted ones times eta^2, undoing radiance compression).
EnergyEstimate whiteFurnace(const BsdfParams& p, Vec3 wo, int n, uint64_t seed) {
    Pcg32 rng(seed);
    const float etap = relativeEtaFor(p, wo);
    double sum = 0.0, sum2 = 0.0;
    EnergyEstimate e;
    for (int i = 0; i < n; ++i) {
        const BsdfSample s = sampleBsdf(p, kIdentity, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
        if (!isFinite(s.weight) || !(s.pdf >= 0.0f) || !isFinite(s.pdf)) e.finite = false;
        const double w = maxComponent(s.weight) * (s.refracted ? double(etap) * etap : 1.0);
        sum += w;
        sum2 += w * w;
        e.maxWeight = std::max(e.maxWeight, w);
    }
    e.mean = sum / n;
    e.standardError = std::sqrt(std::max(0.0, sum2 / n - e.mean * e.mean) / n);
    return e;
}

std::vector<std::pair<const char*, BsdfParams>> whiteMaterials(float roughness, float ior) {
    BsdfParams metal = makeParams({1, 1, 1}, 1.0f, 0.0f, ior, roughness);
    BsdfParams plastic = makeParams({1, 1, 1}, 0.0f, 0.0f, ior, roughness);
    BsdfParams glass = makeParams({1, 1, 1}, 0.0f, 1.0f, ior, roughness);
    BsdfParams coated = plastic;
    coated.clearcoat = 1.0f;
    coated.clearcoatRoughness = roughness * 0.5f;
    BsdfParams mixed = makeParams({1, 1, 1}, 0.3f, 0.4f, ior, roughness);
    mixed.clearcoat = 0.5f;
    mixed.clearcoatRoughness = 0.3f;
    BsdfParams leaf = plastic;        // KHR_materials_diffuse_transmission
    leaf.diffuseTransmission = 0.6f;  // (not with glass: a mixed weight has no one eta^2 to undo)
    BsdfParams velvet = coated;       // KHR_materials_sheen, under the coat
    velvet.sheenColor = {1.0f, 1.0f, 1.0f};
    velvet.sheenRoughness = roughness;
    BsdfParams brushed = metal;  // KHR_materials_anisotropy
    brushed.anisotropy = 0.9f;
    BsdfParams frosted = glass;
    frosted.anisotropy = 0.6f;
    BsdfParams soap = coated;  // KHR_materials_iridescence, a high-index film
    soap.iridescence = 1.0f;
    soap.iridescenceIor = 2.2f;
    soap.iridescenceThickness = 250.0f;
    return {{"metal", metal},     {"plastic", plastic}, {"glass", glass},   {"coated", coated},
            {"mixed", mixed},     {"leaf", leaf},       {"velvet", velvet}, {"brushed", brushed},
            {"frosted", frosted}, {"soap", soap}};
}

constexpr float kStiffRoughness[] = {0.0f, 1e-4f, 0.01f, 0.0316f, 0.0317f, 0.05f, 0.2f, 0.5f, 1.0f};
constexpr float kStiffCosines[] = {1.0f, 0.7f, 0.3f, 0.1f, 0.01f, 1e-6f};
constexpr float kStiffIors[] = {1.0f, 1.0001f, 1.0011f, 1.5f, 2.42f, 4.0f};

TEST(BsdfEnergy, WhiteMaterialsNeverGainEnergy) {
    double worst = 0.0;
    char where[160] = "";
    for (float roughness : kStiffRoughness) {
        for (float ior : kStiffIors) {
            for (const auto& [name, p] : whiteMaterials(roughness, ior)) {
                for (float cosTheta : kStiffCosines) {
                    for (bool inside : {false, true}) {
                        if (inside && !isTransmissive(p)) continue;
                        Vec3 wo = directionAt(cosTheta);
                        if (inside) wo.z = -wo.z;
                        const EnergyEstimate e = whiteFurnace(p, wo, 6000, 99);
                        ASSERT_TRUE(e.finite) << name;
                        EXPECT_LE(e.mean, 1.0 + 4.0 * e.standardError + 1e-3)
                            << name << " roughness " << roughness << " ior " << ior << " cos " << cosTheta
                            << (inside ? " inside" : "");
                        if (e.mean - 4.0 * e.standardError > worst) {
                            worst = e.mean - 4.0 * e.standardError;
                            std::snprintf(where, sizeof(where), "%s roughness %g ior %g cos %g%s", name,
                                          double(roughness), double(ior), double(cosTheta),
                                          inside ? " inside" : "");
                        }
                        // One-lobe white materials: every single weight is at most 1.
                        if (p.metallic == 1.0f || p.transmission == 1.0f) {
                            EXPECT_LE(e.maxWeight, 1.0 + 1e-4)
                                << name << " roughness " << roughness << " cos " << cosTheta;
                        }
                    }
                }
            }
        }
    }
    std::printf("largest white-furnace mean minus 4 standard errors: %.6f (%s)\n", worst, where);
}

// A smooth white dielectric is lossless; a smooth white plastic (specular layer over white
// Lambert) reflects everything the layer lets through; rough ones lose only GGX's
// single-scattering energy (about 40% at roughness 1 for a conductor at normal incidence).
TEST(BsdfEnergy, SmoothWhiteMaterialsAreLossless) {
    for (float cosTheta : {1.0f, 0.5f, 0.1f, 0.01f}) {
        const Vec3 wo = directionAt(cosTheta);
        for (float ior : {1.0f, 1.33f, 1.5f, 2.42f, 4.0f}) {
            const EnergyEstimate glass =
                whiteFurnace(makeParams({1, 1, 1}, 0.0f, 1.0f, ior, 0.0f), wo, 20000, 1);
            EXPECT_NEAR(glass.mean, 1.0, 1e-5);
            const EnergyEstimate inside =
                whiteFurnace(makeParams({1, 1, 1}, 0.0f, 1.0f, ior, 0.0f), {wo.x, wo.y, -wo.z}, 20000, 1);
            EXPECT_NEAR(inside.mean, 1.0, 1e-5);
        }
        const EnergyEstimate plastic =
            whiteFurnace(makeParams({1, 1, 1}, 0.0f, 0.0f, 1.5f, 0.0f), wo, 100000, 2);
        EXPECT_NEAR(plastic.mean, 1.0, 4.0 * plastic.standardError + 1e-3) << cosTheta;
        const EnergyEstimate metal = whiteFurnace(makeParams({1, 1, 1}, 1.0f, 0.0f, 1.5f, 0.0f), wo, 1000, 3);
        EXPECT_NEAR(metal.mean, 1.0, 1e-6);
    }
    // A white diffuse sheet without a specular layer splits all of it between the two sides,
    // the transmitted share being the factor.
    for (float share : {0.0f, 0.3f, 1.0f}) {
        BsdfParams sheet = makeParams({1, 1, 1}, 0.0f, 0.0f, 1.5f, 0.5f);
        sheet.specular = 0.0f;
        sheet.diffuseTransmission = share;
        const Vec3 wo = directionAt(0.6f);
        EXPECT_NEAR(whiteFurnace(sheet, wo, 1000, 5).mean, 1.0, 1e-5) << share;
        const Vec3 below = normalize(Vec3(0.3f, 0.2f, -0.9f));
        EXPECT_NEAR(evalBsdf(sheet, kIdentity, wo, below).x, share * -below.z * kInvPi, 1e-6)
            << "Lambert below (f |cos|), weighted by the share";
    }
    // A white sheen over white Lambert (no specular layer) loses only what the albedo table
    // overestimates (it bounds the sheen's albedo from above, by under 0.02); a white sheen over
    // black reflects its albedo, and at most all of it where the Charlie sheen would exceed 1.
    for (float sheenRoughness : {0.0f, 0.07f, 0.3f, 0.7f, 1.0f}) {
        for (float cosTheta : {1.0f, 0.5f, 0.1f, 0.01f}) {
            const Vec3 wo = directionAt(cosTheta);
            for (float baseColor : {1.0f, 0.0f}) {
                BsdfParams velvet = makeParams(Vec3(baseColor), 0.0f, 0.0f, 1.5f, 0.5f);
                velvet.specular = 0.0f;
                velvet.sheenColor = Vec3(1.0f);
                velvet.sheenRoughness = sheenRoughness;
                const EnergyEstimate e = whiteFurnace(velvet, wo, 200000, 6);
                const double albedo = std::min(1.0f, sheenAlbedo(cosTheta, sheenRoughness));
                const double expected = baseColor > 0.0f ? 1.0 : albedo;
                EXPECT_LE(e.mean, expected + 4.0 * e.standardError + 1e-4)
                    << sheenRoughness << " cos " << cosTheta << " base " << baseColor;
                EXPECT_GE(e.mean, expected - 0.02 - 4.0 * e.standardError)
                    << sheenRoughness << " cos " << cosTheta << " base " << baseColor;
            }
        }
    }
    // Rough white plastic keeps most of its energy: the diffuse base gets what the layer leaves.
    const EnergyEstimate roughPlastic =
        whiteFurnace(makeParams({1, 1, 1}, 0.0f, 0.0f, 1.5f, 0.5f), directionAt(0.7f), 100000, 4);
    EXPECT_GT(roughPlastic.mean, 0.97);
}

// --- Stiff inputs -------------------------------------------------------------------------------

TEST(BsdfStiff, NoNanOrInfAtExtremes) {
    Pcg32 rng(23);
    long evaluated = 0;
    for (float roughness : kStiffRoughness) {
        for (float ior : kStiffIors) {
            for (auto [name, p] : whiteMaterials(roughness, ior)) {
                p.baseColor = {0.8f, 0.3f, 0.05f};
                p.specularColor = {1.0f, 0.2f, 3.0f};
                for (float cosTheta : {1.0f, 0.5f, 1e-3f, 1e-6f, 0.0f, -1e-6f, -0.3f, -1.0f}) {
                    Vec3 wo = directionAt(fabsf(cosTheta));
                    if (cosTheta < 0.0f) wo.z = -wo.z;
                    for (int i = 0; i < 64; ++i) {
                        const BsdfSample s =
                            sampleBsdf(p, kIdentity, wo, rng.uniform(), {rng.uniform(), rng.uniform()});
                        ASSERT_TRUE(isFinite(s.weight))
                            << name << " roughness " << roughness << " ior " << ior;
                        ASSERT_TRUE(isFinite(s.pdf) && s.pdf >= 0.0f) << name;
                        if (!isBlack(s.weight)) {
                            ASSERT_NEAR(length(s.wi), 1.0f, 1e-4f) << name;
                        }
                        const Vec3 wi = randomDirection(rng, rng.uniform() < 0.5f);
                        const Vec3 f = evalBsdf(p, kIdentity, wo, wi);
                        const float pdf = pdfBsdf(p, kIdentity, wo, wi);
                        ASSERT_TRUE(isFinite(f) && minComponent(f) >= 0.0f) << name;
                        ASSERT_TRUE(isFinite(pdf) && pdf >= 0.0f) << name;
                        if (!s.delta && !isBlack(s.weight)) {
                            ASSERT_TRUE(isFinite(evalBsdf(p, kIdentity, wo, s.wi))) << name;
                        }
                        ++evaluated;
                    }
                }
            }
        }
    }
    EXPECT_GT(evaluated, 100000);
}

TEST(BsdfStiff, ExactlyGrazingAndDegenerateInputsGiveNoSample) {
    const BsdfParams p = makeParams({1, 1, 1}, 0.0f, 1.0f, 1.5f, 0.5f);
    const BsdfSample s = sampleBsdf(p, kIdentity, {1.0f, 0.0f, 0.0f}, 0.5f, {0.5f, 0.5f});
    EXPECT_TRUE(isBlack(s.weight));
    const BsdfParams nanIor = makeParams({1, 1, 1}, 0.0f, 1.0f, NAN, 0.5f);
    const BsdfSample n = sampleBsdf(nanIor, kIdentity, directionAt(0.5f), 0.5f, {0.5f, 0.5f});
    EXPECT_TRUE(isFinite(n.weight));
}

}  // namespace
}  // namespace pt

namespace pt {
namespace {

// The combined call light sampling uses must equal the two separate ones bit for bit.
TEST(Bsdf, EvalWithPdfEqualsEvalAndPdf) {
    BsdfParams p{{0.7f, 0.5f, 0.3f}, 0.3f, 0.2f, 1.45f};
    p.roughness = 0.35f;
    p.clearcoat = 0.5f;
    const Frame frame = Frame::fromNormal(normalize(Vec3{0.1f, 0.2f, 0.95f}));
    for (int i = 0; i < 64; ++i) {
        const float a = 0.1f * float(i);
        const Vec3 wo = normalize(Vec3{cosf(a), sinf(a), 0.8f});
        const Vec3 wi = normalize(Vec3{sinf(2 * a), 0.3f, cosf(a)});
        const BsdfEval both = evalBsdfWithPdf(p, frame, wo, wi);
        const Vec3 f = evalBsdf(p, frame, wo, wi);
        EXPECT_EQ(both.value, f);
        EXPECT_EQ(both.pdf, pdfBsdf(p, frame, wo, wi));
    }
}

}  // namespace
}  // namespace pt
