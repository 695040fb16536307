// Scattering media through the whole integrator (issue 15), against what is known without it:
// a white furnace, Beer-Lambert's law, and an analogue random walk written here independently
// (its own distance, absorption and Henyey-Greenstein sampling, by rejection) for the energy a
// sphere of medium loses and for the reflectance of a semi-infinite medium. Then the stiff
// cases: every image finite, and the limits they must approach.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "render/integrator/medium.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addMaterial;
using test::addShape;
using test::meanChannel;
using test::trs;

// A camera at `position` aimed at `target` through a tiny field of view: every pixel sees
// almost exactly the ray from `position` towards `target`.
Scene pinholeScene(Vec3 position, Vec3 target, uint32_t size = 4) {
    Scene scene;
    scene.render = {size, size, 64, 0, 0};
    scene.camera.position = position;
    scene.camera.lookAt = target;
    scene.camera.verticalFovDegrees = 0.01f;
    return scene;
}

// An index-matched volume (the "fog" preset's kind of boundary) with the medium below.
Material indexMatchedMedium(Vec3 attenuationColor, float attenuationDistance, Vec3 scatterColor, float g) {
    Material m;
    m.baseColor = Vec3(1.0f);
    m.transmission = 1.0f;
    m.ior = 1.0f;
    m.thickness = 1.0f;
    m.attenuationColor = attenuationColor;
    m.attenuationDistance = attenuationDistance;
    m.scatterColor = scatterColor;
    m.scatterAnisotropy = g;
    return m;
}

// A medium ball of radius 1 at the origin under a uniform sky, seen across its centre.
Scene mediumBall(const Material& medium, Vec3 sky = Vec3(1.0f)) {
    Scene scene = pinholeScene({0, 0, 5}, {0, 0, 0});
    scene.environment.color = sky;
    addShape(scene, ObjectKind::Sphere, trs({0, 0, 0}), addMaterial(scene, "medium", medium));
    return scene;
}

const IntegratorToggles kNeeMis{true, true, true, false};
const IntegratorToggles kBsdfOnly{false, false, true, false};

// An albedo-1 medium loses nothing: the ball renders the sky, coloured extinction or not, and
// however the light is found (shadow rays through the boundary and the medium, or the phase
// function alone).
TEST(Media, AnAlbedoOneBallInAWhiteFurnaceIsInvisible) {
    for (const IntegratorToggles& toggles : {kNeeMis, kBsdfOnly}) {
        const Material medium = indexMatchedMedium({0.1f, 0.4f, 0.8f}, 0.5f, Vec3(1.0f), 0.6f);
        const std::vector<float> image = test::renderCpu(mediumBall(medium), 1024, toggles);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(meanChannel(image, c), 1.0, 0.01)
                << "channel " << c << ", NEE " << toggles.nextEventEstimation;
    }
}

// Beer-Lambert: through a slab of purely absorbing, index-matched medium the sky keeps
// exp(-sigma d) exactly (no scattering: no noise).
TEST(Media, APurelyAbsorbingSlabTransmitsBeerLambert) {
    Scene scene = pinholeScene({0, 0, 5}, {0, 0, 0});
    scene.environment.color = Vec3(1.0f);
    const Vec3 color{0.2f, 0.5f, 0.9f};
    const float distance = 0.7f, thickness = 0.6f;
    addShape(scene, ObjectKind::Box, trs({0, 0, 0}, {0, 0, 0}, {2, 2, thickness / 2}),
             addMaterial(scene, "slab", indexMatchedMedium(color, distance, Vec3(0.0f), 0.0f)));
    const std::vector<float> image = test::renderCpu(scene, 4, kNeeMis);
    for (int c = 0; c < 3; ++c) {
        const double expected = std::exp(std::log(double(color[c])) / distance * thickness);
        EXPECT_NEAR(meanChannel(image, c), expected, 1e-4 * expected) << "channel " << c;
    }
}

// The analogue random walk: the fraction of walks that leave. Sampled here by rejection,
// independently of henyey_greenstein.h's inversion.
class AnalogueWalk {
public:
    AnalogueWalk(double sigmaT, double albedo, double g) : sigmaT_(sigmaT), albedo_(albedo), g_(g) {}

    // Walks from `p` along `d`; `distanceOut(p, d)` is how far the medium goes on from p along d.
    template <typename DistanceOut>
    double escapeFraction(Vec3 start, Vec3 direction, int walks, DistanceOut distanceOut) {
        int escaped = 0;
        for (int i = 0; i < walks; ++i) {
            double p[3] = {start.x, start.y, start.z}, d[3] = {direction.x, direction.y, direction.z};
            for (int step = 0; step < 100000; ++step) {
                const double t = -std::log(1.0 - uniform_(rng_)) / sigmaT_;
                if (t >= distanceOut(p, d)) {
                    ++escaped;
                    break;
                }
                for (int k = 0; k < 3; ++k) p[k] += t * d[k];
                if (uniform_(rng_) >= albedo_) break;  // absorbed
                scatter(d);
            }
        }
        return double(escaped) / walks;
    }

private:
    double henyeyGreensteinCosineDensity(double mu) const {
        return 0.5 * (1 - g_ * g_) / std::pow(1 + g_ * g_ - 2 * g_ * mu, 1.5);
    }
    void scatter(double d[3]) {
        const double peak = henyeyGreensteinCosineDensity(g_ >= 0 ? 1.0 : -1.0);
        double mu;
        do {
            mu = 2.0 * uniform_(rng_) - 1.0;
        } while (uniform_(rng_) * peak > henyeyGreensteinCosineDensity(mu));
        const double phi = 2.0 * M_PI * uniform_(rng_);
        // Any unit vectors perpendicular to d.
        double a[3] = {std::fabs(d[0]) < 0.9 ? 1.0 : 0.0, std::fabs(d[0]) < 0.9 ? 0.0 : 1.0, 0.0};
        double u[3] = {a[1] * d[2] - a[2] * d[1], a[2] * d[0] - a[0] * d[2], a[0] * d[1] - a[1] * d[0]};
        const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (double& x : u) x /= n;
        const double v[3] = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]};
        const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
        for (int k = 0; k < 3; ++k) d[k] = mu * d[k] + s * (std::cos(phi) * u[k] + std::sin(phi) * v[k]);
    }

    double sigmaT_, albedo_, g_;
    std::mt19937_64 rng_{12345};
    std::uniform_real_distribution<double> uniform_{0.0, 1.0};
};

// A ball of albedo < 1 and coloured extinction: what reaches the camera across its centre is
// the fraction of analogue walks from the same entry point that escape, per channel.
TEST(Media, TheEnergyABallLosesMatchesAnAnalogueWalk) {
    const Vec3 attenuation{0.3f, 0.5f, 0.7f};
    const Vec3 scatter{0.9f, 0.6f, 0.3f};
    const float distance = 0.8f, g = 0.5f;
    const Material material = indexMatchedMedium(attenuation, distance, scatter, g);
    const HomogeneousMedium medium = mediumOf(material);
    const std::vector<float> image = test::renderCpu(mediumBall(material), 4096, kNeeMis);
    const auto sphereExit = [](const double p[3], const double d[3]) {
        const double b = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
        const double c = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1.0;
        return -b + std::sqrt(std::max(0.0, b * b - c));
    };
    for (int c = 0; c < 3; ++c) {
        AnalogueWalk walk(medium.sigmaT[c], medium.sigmaS[c] / medium.sigmaT[c], g);
        const double expected = walk.escapeFraction({0, 0, 1}, {0, 0, -1}, 400000, sphereExit);
        std::cout << "[ figures  ] ball of albedo " << medium.sigmaS[c] / medium.sigmaT[c] << ", g " << g
                  << ", channel " << c << ": rendered " << meanChannel(image, c) << ", analogue walk "
                  << expected << "\n";
        // 65536 samples of a fraction near 0.5: a standard error near 0.002.
        EXPECT_NEAR(meanChannel(image, c), expected, 0.008) << "channel " << c;
    }
}

// A semi-infinite, index-matched, isotropically scattering medium (a box 400 mean free paths
// deep and wide) under a uniform sky, seen at 50 degrees from its normal: by reciprocity the
// radiance seen is the medium's albedo for light arriving along the view, which the analogue
// walk measures. Within 1% for albedos from 0.3 to 0.99.
TEST(Media, ASemiInfiniteMediumReflectsAsTheAnalogueWalkSays) {
    const float angle = 50.0f * kPi / 180.0f;
    const Vec3 view{std::sin(angle), std::cos(angle), 0.0f};  // from the surface to the camera
    for (const float albedo : {0.3f, 0.8f, 0.99f}) {
        SCOPED_TRACE(albedo);
        // Extinction 1 per unit (attenuation e^-1 over 1); multiscatter colour chosen so that
        // van de Hulst's relation gives the single-scattering albedo wanted.
        float scatterColor = 0.5f;
        for (float lo = 0.0f, hi = 1.0f, i = 0; i < 40; ++i) {
            scatterColor = 0.5f * (lo + hi);
            (vanDeHulstSingleScatterAlbedo(scatterColor, 0.0f) < albedo ? lo : hi) = scatterColor;
        }
        Scene scene = pinholeScene(view * 10.0f, {0, 0, 0});
        scene.environment.color = Vec3(1.0f);
        const Material m = indexMatchedMedium(Vec3(std::exp(-1.0f)), 1.0f, Vec3(scatterColor), 0.0f);
        addShape(scene, ObjectKind::Box, trs({0, -200, 0}, {0, 0, 0}, Vec3(200.0f)),
                 addMaterial(scene, "deep", m));
        const std::vector<float> image = test::renderCpu(scene, 4096, kNeeMis);
        const HomogeneousMedium medium = mediumOf(m);
        AnalogueWalk walk(1.0, medium.sigmaS.x / medium.sigmaT.x, 0.0);
        const auto halfSpaceExit = [](const double p[3], const double d[3]) {
            return d[1] > 0.0 ? -p[1] / d[1] : INFINITY;
        };
        const double expected = walk.escapeFraction({0, 0, 0}, -view, 400000, halfSpaceExit);
        std::cout << "[ figures  ] half-space of albedo " << albedo << ": rendered " << meanChannel(image, 1)
                  << ", analogue walk " << expected << "\n";
        EXPECT_NEAR(meanChannel(image, 1), expected, 0.01 * expected);
    }
}

// A subsurface ball next to a small lamp, in the stiff cases: finite everywhere, and the limits
// they approach. Mean free paths 1e4 times the ball's size make clear glass of it; 1e-4 times
// make a surface that scatters back what enters near where it entered.
Scene subsurfaceBall(const Material& m) {
    Scene scene;
    scene.render = {16, 16, 64, 0, 0};
    scene.camera.position = {0, 0, 4};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.verticalFovDegrees = 35;
    scene.environment.color = Vec3(0.2f);
    addShape(scene, ObjectKind::Sphere, trs({0, 0, 0}), addMaterial(scene, "ball", m));
    addShape(scene, ObjectKind::Sphere, trs({1.5f, 1.5f, 1.0f}, {0, 0, 0}, Vec3(0.3f)),
             addMaterial(scene, "lamp", test::emitter(Vec3(20.0f))));
    return scene;
}

Material wax(float radius, Vec3 color, float g) {
    Material m;
    m.subsurface = 1.0f;
    m.subsurfaceColor = color;
    m.subsurfaceRadius = radius;
    m.subsurfaceRadiusScale = Vec3(1.0f);
    m.scatterAnisotropy = g;
    m.baseColor = Vec3(1.0f);
    m.roughness = 0.3f;
    return m;
}

TEST(Media, StiffSubsurfaceCasesStayFinite) {
    struct Case {
        const char* name;
        Material m;
    };
    const Case cases[] = {
        {"albedo 1", wax(0.1f, Vec3(1.0f), 0.0f)},     {"albedo near 0", wax(0.1f, Vec3(1e-4f), 0.0f)},
        {"radius 1e-4", wax(1e-4f, Vec3(0.8f), 0.0f)}, {"radius 1e4", wax(1e4f, Vec3(0.8f), 0.0f)},
        {"g -0.99", wax(0.1f, Vec3(0.8f), -0.99f)},    {"g 0.99", wax(0.1f, Vec3(0.8f), 0.99f)},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::vector<float> image =
            test::renderCpu(subsurfaceBall(c.m), 64, kNeeMis);  // finite: checked there
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_GT(meanChannel(image, ch), 0.0);
            EXPECT_LT(meanChannel(image, ch), 10.0);
        }
    }
}

// The base colour tints glass, not what enters the subsurface medium (the medium colours that).
TEST(Media, AVeryThinSubsurfaceMediumIsClearGlass) {
    Material glass = wax(1e4f, Vec3(0.8f), 0.0f);
    glass.subsurface = 0.0f;
    glass.transmission = 1.0f;
    Material thinWax = wax(1e4f, Vec3(0.8f), 0.0f);
    thinWax.baseColor = {0.3f, 0.6f, 0.9f};
    const std::vector<float> thin = test::renderCpu(subsurfaceBall(thinWax), 256, kNeeMis);
    const std::vector<float> clear = test::renderCpu(subsurfaceBall(glass), 256, kNeeMis);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(meanChannel(thin, c) / meanChannel(clear, c), 1.0, 0.01) << c;
}

// Light sampled from inside fog and found by the phase function agree, for a lamp inside the
// fog and one outside it, seen through the index-matched boundary.
TEST(Media, LightInsideAndOutsideFogIsFoundAlikeByBothStrategies) {
    struct Lamp {
        Vec3 centre;
        float radius;
    };
    for (const Lamp lamp : {Lamp{{0.3f, 0.2f, 0.0f}, 0.2f}, Lamp{{2.0f, 1.0f, 0.3f}, 0.6f}}) {
        Scene scene = subsurfaceBall(indexMatchedMedium(Vec3(0.5f), 1.0f, Vec3(0.8f, 0.7f, 0.6f), 0.3f));
        scene.environment.color = Vec3(0.0f);
        scene.objects[1].transform = trs(lamp.centre, {0, 0, 0}, Vec3(lamp.radius));
        scene.instances[1].objectToWorld = scene.objects[1].transform.toAffine();
        const std::vector<float> nee = test::renderCpu(scene, 2048, kNeeMis);
        const std::vector<float> phase = test::renderCpu(scene, 2048, kBsdfOnly);
        std::cout << "[ figures  ] lamp at x = " << lamp.centre.x << ": NEE+MIS / phase sampling alone "
                  << meanChannel(nee, 1) / meanChannel(phase, 1) << " (green)\n";
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(meanChannel(nee, c) / meanChannel(phase, c), 1.0, 0.03)
                << "lamp at " << lamp.centre.x << ", channel " << c;
        }
    }
}

}  // namespace
}  // namespace pt
