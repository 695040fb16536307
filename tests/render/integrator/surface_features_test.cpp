// Integrator features beyond plain BSDFs: alpha coverage (MASK, BLEND) for camera, bounce and
// shadow rays; tangent-space normal maps (file tangents and UV-derived ones); Beer-Lambert
// absorption inside volumes; unlit, diffusely transmitting and sheen surfaces; and the firefly
// clamp.
#include <gtest/gtest.h>

#include <cmath>

#include "render/integrator/path_tracer.h"
#include "render/materials/sheen.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addFloatTexture;
using test::addLight;
using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::floorPointScene;
using test::meanChannel;
using test::trs;

const IntegratorToggles kNeeMis{true, true, true, false};
constexpr float kAlbedo = 0.7f;

// A camera that sees only a quad facing it, with a constant sky behind.
Scene quadInFrontOfSky(const Material& quad, Vec3 sky) {
    Scene scene;
    scene.render = {16, 16, 4, 0, 0};
    scene.environment.color = sky;
    scene.camera.position = {0, 0, 3};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.verticalFovDegrees = 10;
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}, {90, 0, 0}), addMaterial(scene, "quad", quad));
    return scene;
}

Material blackWithAlpha(AlphaMode mode, float alpha) {
    Material m = diffuse(Vec3(0.0f));
    m.alphaMode = mode;
    m.alpha = alpha;
    return m;
}

// glTF doubleSided = false culls back faces: a single-sided quad seen from behind is not
// there, for camera rays and for shadow rays; seen from the front, or double-sided, it is.
TEST(BackFaceCulling, SingleSidedSurfacesAreInvisibleFromBehind) {
    const Vec3 sky{0.2f, 0.4f, 0.6f};
    Material single = diffuse(Vec3(0.0f));
    single.doubleSided = 0;
    Scene scene = quadInFrontOfSky(single, sky);  // rotated +90 about X, the quad faces the camera
    const std::vector<float> front = test::renderCpu(scene, 2);
    for (size_t i = 0; i < front.size() / 4; ++i) ASSERT_EQ(front[i * 4 + 2], 0.0f) << "pixel " << i;

    scene.instances[0].objectToWorld = trs({0, 0, 0}, {-90, 0, 0}).toAffine();  // now facing away
    const std::vector<float> hidden = test::renderCpu(scene, 2);
    for (size_t i = 0; i < hidden.size() / 4; ++i) ASSERT_FLOAT_EQ(hidden[i * 4 + 2], sky.z) << "pixel " << i;

    single.doubleSided = 1;
    scene.materials[0].params = single;
    const std::vector<float> twoSided = test::renderCpu(scene, 2);
    for (size_t i = 0; i < twoSided.size() / 4; ++i) ASSERT_EQ(twoSided[i * 4 + 2], 0.0f) << "pixel " << i;

    // Glass is never culled: it must be met from inside to refract out.
    Material glass = single;
    glass.doubleSided = 0;
    glass.transmission = 1.0f;
    EXPECT_FALSE(cullsBackFaces(glass));
}

TEST(Alpha, BlendIsStochasticCoverageForCameraRays) {
    const std::vector<float> image =
        test::renderCpu(quadInFrontOfSky(blackWithAlpha(AlphaMode::Blend, 0.3f), Vec3(1.0f)), 256);
    EXPECT_NEAR(meanChannel(image, 0), 0.7, 0.01);
}

TEST(Alpha, MaskCutsAtTheCutoff) {
    const Vec3 sky{0.2f, 0.4f, 0.6f};
    const std::vector<float> hidden =
        test::renderCpu(quadInFrontOfSky(blackWithAlpha(AlphaMode::Mask, 0.3f), sky), 2);
    for (size_t i = 0; i < hidden.size() / 4; ++i) ASSERT_FLOAT_EQ(hidden[i * 4 + 2], sky.z) << "pixel " << i;
    const std::vector<float> shown =
        test::renderCpu(quadInFrontOfSky(blackWithAlpha(AlphaMode::Mask, 0.7f), sky), 2);
    for (size_t i = 0; i < shown.size() / 4; ++i) ASSERT_EQ(shown[i * 4 + 2], 0.0f) << "pixel " << i;
    // The texture's alpha multiplies the factor: left half transparent, right half opaque.
    Scene textured = quadInFrontOfSky(blackWithAlpha(AlphaMode::Mask, 1.0f), sky);
    textured.materials[0].params.baseColorTexture.texture =
        addFloatTexture(textured, 2, 1, [](uint32_t x, uint32_t) {
            return Vec4{1, 1, 1, x == 0 ? 0.0f : 1.0f};
        });
    textured.textures.back().nearest = true;
    const std::vector<float> half = test::renderCpu(textured, 2);
    EXPECT_FLOAT_EQ(half[(8 * 16 + 2) * 4 + 2], sky.z);
    EXPECT_EQ(half[(8 * 16 + 13) * 4 + 2], 0.0f);
}

// A directional light straight down through a transparent sheet above the floor point.
Scene shadowThroughSheet(const Material& sheet) {
    Scene scene = floorPointScene(kAlbedo);
    addLight(scene, LightType::Directional, Vec3(1.0f), 3.0f, {}, {0, -1, 0});
    addShape(scene, ObjectKind::Quad, trs({0, 1, 0}, {0, 0, 0}, {2, 1, 2}),
             addMaterial(scene, "sheet", sheet));
    return scene;
}

TEST(Alpha, ShadowRaysPassTransparentSurfaces) {
    const double lit = kAlbedo / kPi * 3.0;
    EXPECT_NEAR(
        meanChannel(
            test::renderCpu(shadowThroughSheet(blackWithAlpha(AlphaMode::Blend, 0.4f)), 1024, kNeeMis), 0) /
            lit,
        0.6, 0.01);
    EXPECT_NEAR(
        meanChannel(test::renderCpu(shadowThroughSheet(blackWithAlpha(AlphaMode::Mask, 0.4f)), 4, kNeeMis),
                    0) /
            lit,
        1.0, 1e-3);
    EXPECT_EQ(meanChannel(
                  test::renderCpu(shadowThroughSheet(blackWithAlpha(AlphaMode::Mask, 0.6f)), 4, kNeeMis), 0),
              0.0);
    // Many transparent layers in a row end the search (as opaque) instead of looping forever.
    Scene stack = shadowThroughSheet(blackWithAlpha(AlphaMode::Mask, 0.0f));
    for (int i = 0; i < 80; ++i) addShape(stack, ObjectKind::Quad, trs({0, 1.0f + 0.01f * i, 0}), 1);
    EXPECT_EQ(meanChannel(test::renderCpu(stack, 1, kNeeMis), 0), 0.0);
}

// Encodes a tangent-space normal as a normal texture texel.
Vec4 normalTexel(Vec3 n) { return {0.5f * n.x + 0.5f, 0.5f * n.y + 0.5f, 0.5f * n.z + 0.5f, 1.0f}; }

// The floor point lit by a directional light coming from `toLight`, its normal texture
// holding the constant tangent-space normal `mapped`.
Scene normalMappedFloor(Vec3 mapped, Vec3 toLight) {
    Scene scene = floorPointScene(kAlbedo);
    Material& floor = scene.materials[0].params;
    floor.normalTexture.texture =
        addFloatTexture(scene, 2, 2, [&](uint32_t, uint32_t) { return normalTexel(mapped); });
    addLight(scene, LightType::Directional, Vec3(1.0f), 2.0f, {}, -toLight);
    return scene;
}

TEST(NormalMap, TiltsTheShadingNormalInTheTangentFrame) {
    const float a = 30.0f * kPi / 180.0f;
    const double flat = kAlbedo / kPi * 2.0;
    // The built-in quad's U runs along +X and its V along -Z, so the tangent is +X and the
    // bitangent ("up" in the image, decreasing V) is +Z.
    const Vec3 alongX{std::sin(a), std::cos(a), 0}, alongZ{0, std::cos(a), std::sin(a)};
    const Vec3 tiltedX{std::sin(a), 0, std::cos(a)}, tiltedY{0, std::sin(a), std::cos(a)};
    EXPECT_NEAR(meanChannel(test::renderCpu(normalMappedFloor(tiltedX, alongX), 4, kNeeMis), 0) / flat, 1.0,
                1e-3);
    EXPECT_NEAR(meanChannel(test::renderCpu(normalMappedFloor(tiltedY, alongZ), 4, kNeeMis), 0) / flat, 1.0,
                1e-3);
    EXPECT_NEAR(meanChannel(test::renderCpu(normalMappedFloor(tiltedY, alongX), 4, kNeeMis), 0) / flat,
                std::cos(a) * std::cos(a), 1e-3)
        << "tilted across the light: n = (0, cos a, sin a), wi = (sin a, cos a, 0)";
    // normalScale scales the tangent-plane part.
    Scene unscaled = normalMappedFloor(tiltedX, alongX);
    unscaled.materials[0].params.normalScale = 0.0f;
    EXPECT_NEAR(meanChannel(test::renderCpu(unscaled, 4, kNeeMis), 0) / flat, std::cos(a), 1e-3);
}

// A floor quad (facing +Y, UVs as the built-in quad) whose file tangents point along +Z.
TEST(NormalMap, UsesTheFileTangentsAndTheirHandedness) {
    const float a = 30.0f * kPi / 180.0f;
    for (const float w : {1.0f, -1.0f}) {
        Scene scene = normalMappedFloor({0, std::sin(a), std::cos(a)}, {w * std::sin(a), std::cos(a), 0});
        Mesh& quad = scene.meshes[scene.instances[0].mesh];
        quad.tangents.assign(quad.positions.size(),
                             Vec4{0, 0, 1, w});  // bitangent = cross(+Y, +Z) w = w * +X
        EXPECT_NEAR(meanChannel(test::renderCpu(scene, 4, kNeeMis), 0) / (kAlbedo / kPi * 2.0), 1.0, 1e-3)
            << "w " << w;
    }
}

// Looking through the centre of an index-matched sphere of radius 1 (no refraction, no
// reflection): the sky is attenuated by attenuationColor^(2 / attenuationDistance).
TEST(Volume, BeerLambertAttenuatesAlongThePathInside) {
    Material glass;
    glass.baseColor = Vec3(1.0f);
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    glass.ior = 1.0f;
    glass.thickness = 1.0f;
    glass.attenuationColor = {0.5f, 0.8f, 1.0f};
    glass.attenuationDistance = 4.0f;
    Scene scene;
    scene.render = {4, 4, 8, 0, 0};
    scene.environment.color = Vec3(1.0f);
    scene.camera.position = {0, 0, 5};
    scene.camera.verticalFovDegrees = 0.01f;
    addShape(scene, ObjectKind::Sphere, trs({0, 0, 0}), addMaterial(scene, "glass", glass));
    std::vector<float> image = test::renderCpu(scene, 4);
    EXPECT_NEAR(meanChannel(image, 0), std::pow(0.5, 0.5), 1e-4);
    EXPECT_NEAR(meanChannel(image, 1), std::pow(0.8, 0.5), 1e-4);
    EXPECT_NEAR(meanChannel(image, 2), 1.0, 1e-4);
    // Thin-walled (thickness 0): no volume, no absorption.
    scene.materials[0].params.thickness = 0.0f;
    image = test::renderCpu(scene, 4);
    EXPECT_NEAR(meanChannel(image, 0), 1.0, 1e-4);
}

// The clamp limits indirect contributions only: with a tiny limit, a scene renders as its
// direct lighting plus at most that limit per bounce.
// KHR_materials_unlit: the camera sees the base colour, exactly, whatever lights the scene; a
// lit (diffuse) quad of that colour under the same sky does not look like it.
TEST(Unlit, TheCameraSeesTheBaseColourAsIs) {
    Material poster = diffuse({0.2f, 0.5f, 0.9f});
    poster.unlit = 1;
    Scene scene = quadInFrontOfSky(poster, Vec3(3.0f));
    addLight(scene, LightType::Point, {1, 1, 1}, 50.0f, {0, 0, 2});
    CpuBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    backend.render(4);
    EXPECT_NE(backend.stats().features & feature::kUnlit, 0u);
    const std::vector<float> image = test::beautyOf(backend);
    for (size_t i = 0; i < image.size(); i += 4) {
        ASSERT_NEAR(image[i], 0.2f, 1e-6f) << "pixel " << i / 4;
        ASSERT_NEAR(image[i + 1], 0.5f, 1e-6f);
        ASSERT_NEAR(image[i + 2], 0.9f, 1e-6f);
    }
    poster.unlit = 0;
    const std::vector<float> lit = test::renderCpu(quadInFrontOfSky(poster, Vec3(3.0f)), 4, kNeeMis);
    EXPECT_GT(std::fabs(meanChannel(lit, 0) - 0.2), 0.1) << "a lit quad is shaded";
}

// Paths that meet an unlit surface end there with its colour: a floor under an unlit ceiling,
// with no light in the scene, is lit by it (BSDF sampling finds it; it is no light NEE samples);
// the same ceiling lit normally leaves the floor black.
TEST(Unlit, LightsWhatSeesItButIsNoLight) {
    for (const bool unlit : {true, false}) {
        Scene scene = floorPointScene(0.5f, 2);
        scene.environment.color = Vec3(0.0f);
        Material ceiling = diffuse({1.0f, 1.0f, 1.0f});
        ceiling.unlit = unlit ? 1u : 0u;
        addShape(scene, ObjectKind::Quad, trs({0, 2, 0}, {180, 0, 0}, {100, 1, 100}),
                 addMaterial(scene, "ceiling", ceiling), "ceiling");
        CpuBackend backend;
        backend.setToggles(kNeeMis);
        backend.sync(scene, SceneChanges::All, {});
        backend.render(64);
        EXPECT_EQ(backend.stats().nonfiniteSamples, 0u);
        const double floor = meanChannel(test::beautyOf(backend), 0);
        if (unlit) {
            // A ceiling filling the hemisphere at radiance 1 over a 0.5 floor: 0.5, less the
            // ceiling's far edge (100 units wide, 2 up: a few thousandths).
            EXPECT_NEAR(floor, 0.5, 0.03);
        } else {
            EXPECT_EQ(floor, 0.0);
        }
    }
}

// KHR_materials_diffuse_transmission: a black sheet (no diffuse reflection, no specular layer)
// that transmits diffusely with colour 0.5, in front of a sky of 2 on every side, shows the sky
// behind it: 0.5 * 2 = 1. Without the transmission it is black.
TEST(DiffuseTransmission, ASheetShowsTheLightBehindIt) {
    for (const float share : {1.0f, 0.0f}) {
        Material sheet = diffuse(Vec3(0.0f));
        sheet.specular = 0.0f;
        sheet.diffuseTransmission = share;
        sheet.diffuseTransmissionColor = Vec3(0.5f);
        Scene scene = quadInFrontOfSky(sheet, Vec3(2.0f));
        scene.render.maxDepth = 2;
        CpuBackend backend;
        backend.setToggles(kNeeMis);
        backend.sync(scene, SceneChanges::All, {});
        backend.render(256);
        EXPECT_EQ(share > 0.0f, (backend.stats().features & feature::kDiffuseTransmission) != 0u);
        EXPECT_NEAR(meanChannel(test::beautyOf(backend), 1), share, 0.02) << "share " << share;
    }
}

// KHR_materials_sheen: a white sheen on a black base without a specular layer, under a sky of
// 2 on every side, seen at 60 degrees from its normal (the camera's field is 10 degrees, so the
// middle pixels see it within a degree of that) reflects the sky times the sheen's albedo there;
// without the sheen it is black.
TEST(Sheen, ReflectsTheSkyByItsAlbedo) {
    for (const float sheenRoughness : {0.3f, 1.0f}) {
        Material velvet = diffuse(Vec3(0.0f));
        velvet.specular = 0.0f;
        velvet.sheenColor = Vec3(1.0f);
        velvet.sheenRoughness = sheenRoughness;
        Scene scene = quadInFrontOfSky(velvet, Vec3(2.0f));
        scene.instances[0].objectToWorld = trs({0, 0, 0}, {30, 0, 0}).toAffine();
        scene.render.maxDepth = 2;
        CpuBackend backend;
        backend.setToggles(kNeeMis);
        backend.sync(scene, SceneChanges::All, {});
        backend.render(512);
        EXPECT_NE(backend.stats().features & feature::kSheen, 0u);
        const std::vector<float> image = test::beautyOf(backend);
        double sum = 0.0;
        for (uint32_t y = 6; y < 10; ++y) {
            for (uint32_t x = 6; x < 10; ++x) sum += image[(y * 16 + x) * 4 + 1];
        }
        const double expected = 2.0 * sheenAlbedo(0.5f, sheenRoughness);
        EXPECT_NEAR(sum / 16.0, expected, 0.02 + 0.03 * expected) << "sheen roughness " << sheenRoughness;
    }
}

TEST(FireflyClamp, LimitsIndirectLightOnly) {
    Scene scene = floorPointScene(kAlbedo, 6);
    scene.camera.position = {0, 0.5f, 0.3f};
    addShape(scene, ObjectKind::Quad, trs({0, 1.5f, 0}, {180, 0, 0}, {0.3f, 1, 0.3f}),
             addMaterial(scene, "lamp", test::emitter(Vec3(20.0f))));
    addShape(scene, ObjectKind::Box, trs({0.6f, 0.5f, 0}, {0, 0, 0}, Vec3(0.3f)),
             addMaterial(scene, "box", diffuse(Vec3(0.9f))));
    IntegratorToggles clamped = kNeeMis;
    clamped.clampRadiance = 1e-3f;
    const double full = meanChannel(test::renderCpu(scene, 64, kNeeMis), 0);
    const double limited = meanChannel(test::renderCpu(scene, 64, clamped), 0);
    scene.render.maxDepth = 1;
    const double direct = meanChannel(test::renderCpu(scene, 64, kNeeMis), 0);
    EXPECT_GT(full, direct * 1.05) << "the scene has indirect light";
    EXPECT_GE(limited, direct);
    EXPECT_LE(limited, direct + 2 * 6 * 1e-3);
}

}  // namespace
}  // namespace pt
