// Every kind of light against its analytic irradiance at a diffuse point (floorPointScene:
// each pixel's radiance is albedo / pi x E): emissive spheres, a uniform sky (constant and
// image), point, spot and directional lights, and stiff lights (tiny and very bright).
#include <gtest/gtest.h>

#include <cmath>

#include "render/integrator/path_tracer.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addFloatTexture;
using test::addLight;
using test::addMaterial;
using test::addShape;
using test::emitter;
using test::floorPointScene;
using test::meanChannel;
using test::trs;

constexpr float kAlbedo = 0.7f;

struct Variant {
    const char* name;
    IntegratorToggles toggles;
    uint32_t spp;
    double tolerance;  // relative
};

const IntegratorToggles kNeeMis{true, true, true, false};
const IntegratorToggles kNeeOnly{true, false, true, false};
const IntegratorToggles kBsdfOnly{false, false, true, false};

void expectRadiance(const Scene& scene, double expected, std::initializer_list<Variant> variants) {
    for (const Variant& v : variants) {
        const std::vector<float> image = test::renderCpu(scene, v.spp, v.toggles);
        const double mean = meanChannel(image, 1);
        EXPECT_NEAR(mean / expected, 1.0, v.tolerance) << v.name << ": " << mean << " vs " << expected;
    }
}

// A sphere of radius r whose centre lies at distance d along the normal: E = pi L (r/d)^2.
TEST(LightIrradiance, SphereLightMatchesPiLTimesRadiusOverDistanceSquared) {
    const float radiance = 3.0f, radius = 0.5f, distance = 2.0f;
    Scene scene = floorPointScene(kAlbedo);
    addShape(scene, ObjectKind::Sphere, trs({0, distance, 0}, {0, 0, 0}, Vec3(radius)),
             addMaterial(scene, "lamp", emitter(Vec3(radiance))));
    const double expected = kAlbedo * radiance * (radius / distance) * (radius / distance);
    expectRadiance(scene, expected,
                   {{"nee+mis", kNeeMis, 256, 0.01},
                    {"nee only", kNeeOnly, 256, 0.01},
                    {"bsdf only", kBsdfOnly, 4096, 0.03}});
}

// The same sphere seen through a non-uniformly scaled instance is an ellipsoid, which NEE
// does not sample: BSDF sampling alone (MIS weight 1) still finds it. Squashing it along the
// normal keeps its silhouette from the floor point nearly that of the sphere.
TEST(LightIrradiance, EllipsoidLightIsFoundByBsdfSamplingWithFullWeight) {
    Scene scene = floorPointScene(kAlbedo);
    addShape(scene, ObjectKind::Sphere, trs({0, 2, 0}, {0, 0, 0}, {0.5f, 0.5001f, 0.5f}),
             addMaterial(scene, "lamp", emitter(Vec3(3.0f))));
    const double expected = kAlbedo * 3.0 * 0.0625;
    expectRadiance(scene, expected, {{"nee+mis", kNeeMis, 4096, 0.03}});
}

// A uniform sky of radiance L: E = pi L, for a constant colour and a constant image.
TEST(LightIrradiance, UniformSkyGivesPiL) {
    const float sky = 0.8f;
    Scene constant = floorPointScene(kAlbedo);
    constant.environment.color = Vec3(sky);
    expectRadiance(constant, kAlbedo * sky,
                   {{"nee+mis", kNeeMis, 512, 0.01}, {"bsdf only", kBsdfOnly, 512, 0.01}});

    Scene image = floorPointScene(kAlbedo);
    image.environment.texture = addFloatTexture(image, 16, 8, [&](uint32_t, uint32_t) {
        return Vec4{sky, sky, sky, 1};
    });
    image.environment.intensity = 2.0f;
    expectRadiance(image, kAlbedo * sky * 2.0,
                   {{"nee+mis", kNeeMis, 512, 0.01}, {"nee only", kNeeOnly, 512, 0.01}});
}

// Point light: E = I cos(theta) / d^2. Delta lights have no variance here.
TEST(LightIrradiance, PointLightGivesIntensityCosOverDistanceSquared) {
    Scene scene = floorPointScene(kAlbedo);
    const Vec3 position{1.0f, 2.0f, 0.5f};
    addLight(scene, LightType::Point, {1.0f, 0.5f, 0.25f}, 40.0f, position);
    const double d2 = lengthSquared(position), cosTheta = position.y / std::sqrt(d2);
    const double expected = kAlbedo / kPi * 40.0 * 0.5 * cosTheta / d2;  // green channel
    expectRadiance(scene, expected, {{"nee+mis", kNeeMis, 4, 1e-3}, {"nee only", kNeeOnly, 4, 1e-3}});
    EXPECT_EQ(meanChannel(test::renderCpu(scene, 4, kBsdfOnly), 1), 0.0) << "only NEE reaches delta lights";
}

// Spot light 2 units above the point, its axis tilted by `tilt` degrees: full intensity
// inside the inner cone, none outside the outer one, glTF's smooth falloff between.
TEST(LightIrradiance, SpotLightFallsOffBetweenInnerAndOuterCone) {
    const float inner = 20.0f, outer = 40.0f, intensity = 30.0f;
    for (const float tilt : {0.0f, 10.0f, 25.0f, 30.0f, 35.0f, 45.0f}) {
        Scene scene = floorPointScene(kAlbedo);
        const float a = tilt * kPi / 180.0f;
        addLight(scene, LightType::Spot, Vec3(1.0f), intensity, {0, 2, 0}, {std::sin(a), -std::cos(a), 0});
        scene.lights.back().innerConeDegrees = inner;
        scene.lights.back().outerConeDegrees = outer;
        const double cosInner = std::cos(inner * kPi / 180), cosOuter = std::cos(outer * kPi / 180);
        const double t = std::clamp((std::cos(a) - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
        const double expected = kAlbedo / kPi * intensity * t * t / 4.0;
        const double mean = meanChannel(test::renderCpu(scene, 4, kNeeMis), 1);
        if (expected == 0.0) {
            EXPECT_EQ(mean, 0.0) << "tilt " << tilt;
        } else {
            EXPECT_NEAR(mean / expected, 1.0, 1e-3) << "tilt " << tilt;
        }
    }
}

// Directional light of illuminance E (lux): E cos(theta) on the floor.
TEST(LightIrradiance, DirectionalLightGivesLuxTimesCos) {
    Scene scene = floorPointScene(kAlbedo);
    const Vec3 direction = normalize(Vec3{-1.0f, -2.0f, 0.3f});
    addLight(scene, LightType::Directional, Vec3(1.0f), 5.0f, {0, 0, 0},
             direction * 3.0f);  // need not be unit
    const double expected = kAlbedo / kPi * 5.0 * -direction.y;
    expectRadiance(scene, expected, {{"nee+mis", kNeeMis, 4, 1e-3}});
    // Blocked by a box in its path (and only in its path).
    addShape(scene, ObjectKind::Box, trs(-direction * 3.0f, {0, 0, 0}, Vec3(0.3f)),
             addMaterial(scene, "blocker", test::diffuse(Vec3(0.5f))));
    EXPECT_EQ(meanChannel(test::renderCpu(scene, 4, kNeeMis), 1), 0.0);
}

// Form factor from a differential area to a parallel a x b rectangle whose corner lies
// straight above it at height h (Howell's catalogue, C-11).
double cornerFormFactor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2 * kPi);
}

// Radiance 1e6 from an area of 1e-6: finite, and the analytic answer, for a sphere and a quad.
TEST(LightIrradiance, StiffLightsAreFiniteAndMatchTheAnalyticIrradiance) {
    const float radiance = 1e6f, area = 1e-6f;
    Scene sphere = floorPointScene(kAlbedo);
    const float radius = std::sqrt(area / (4 * kPi));
    addShape(sphere, ObjectKind::Sphere, trs({0, 1, 0}, {0, 0, 0}, Vec3(radius)),
             addMaterial(sphere, "tiny", emitter(Vec3(radiance))));
    expectRadiance(sphere, kAlbedo * radiance * radius * radius, {{"nee+mis", kNeeMis, 64, 0.01}});

    Scene quad = floorPointScene(kAlbedo);
    const float half = 0.5f * std::sqrt(area);
    addShape(quad, ObjectKind::Quad, trs({0, 1, 0}, {180, 0, 0}, {half, 1, half}),
             addMaterial(quad, "tiny", emitter(Vec3(radiance))));
    expectRadiance(quad, kAlbedo * radiance * 4 * cornerFormFactor(half, half, 1.0),
                   {{"nee+mis", kNeeMis, 64, 0.01}, {"nee only", kNeeOnly, 64, 0.01}});
}

// A mirroring instance transform keeps the emitter's front face (glTF: a negative
// determinant makes the clockwise side the front): NEE and BSDF sampling both see it lit.
TEST(LightIrradiance, MirroredEmitterKeepsItsFrontFaceForBothStrategies) {
    Scene scene = floorPointScene(kAlbedo);
    addShape(scene, ObjectKind::Quad, trs({0, 1, 0}, {180, 0, 0}, {-0.5f, 1, 0.5f}),
             addMaterial(scene, "lamp", emitter(Vec3(5.0f))));
    const double expected = kAlbedo * 5.0 * 4 * cornerFormFactor(0.5, 0.5, 1.0);
    expectRadiance(scene, expected, {{"nee+mis", kNeeMis, 256, 0.01}, {"bsdf only", kBsdfOnly, 4096, 0.03}});
}

// Edits of the lights or the environment reach the light table without a full recompile.
TEST(LightIrradiance, EditedLightsAndEnvironmentReachTheLightTable) {
    Scene scene = floorPointScene(kAlbedo);
    addLight(scene, LightType::Point, Vec3(1.0f), 10.0f, {0, 2, 0});
    CpuBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    auto render = [&] {
        backend.render(4);
        std::vector<float> image;
        backend.readBeauty(image);
        return meanChannel(image, 0);
    };
    const double point = kAlbedo / kPi * 10.0 / 4.0;
    EXPECT_NEAR(render() / point, 1.0, 1e-3);
    scene.lights[0].intensity = 20.0f;
    EXPECT_EQ(backend.sync(scene, SceneChanges::Lights, {}).action, "lights")
        << "the light table, and no compile";
    EXPECT_NEAR(render() / point, 2.0, 2e-3);
    scene.environment.color = Vec3(0.5f);
    backend.sync(scene, SceneChanges::Environment, {});
    backend.render(508);
    std::vector<float> image;
    backend.readBeauty(image);
    EXPECT_NEAR(meanChannel(image, 0) / (2.0 * point + kAlbedo * 0.5), 1.0, 0.01);
}

}  // namespace
}  // namespace pt
