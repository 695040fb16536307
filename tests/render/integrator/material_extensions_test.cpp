// KHR_materials_anisotropy and KHR_materials_dispersion through the integrator: the anisotropy
// direction follows the mesh's tangent space, its rotation and its texture; dispersive glass
// keeps a white furnace white and splits white light into colours, which glass without
// dispersion never does.
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
using test::meanChannel;
using test::trs;

const IntegratorToggles kNeeMis{true, true, true, false};
constexpr uint32_t kSize = 32;

// A brushed metal quad facing the camera (U along the image's x), lit by a point light at the
// camera: its highlight is a streak along the anisotropy direction.
Scene brushedQuad(const Material& metal) {
    Scene scene;
    scene.render = {kSize, kSize, 1, 0, 0};
    scene.camera.position = {0, 0, 3};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.verticalFovDegrees = 40;
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}, {90, 0, 0}), addMaterial(scene, "brushed", metal));
    addLight(scene, LightType::Point, Vec3(1.0f), 20.0f, {0, 0, 3});
    return scene;
}

Material brushedMetal(float rotation) {
    Material m = test::diffuse(Vec3(0.9f));
    m.metallic = 1.0f;
    m.roughness = 0.3f;
    m.anisotropyStrength = 1.0f;
    m.anisotropyRotation = rotation;
    return m;
}

// The spread of the highlight along the image's x and y: second moments of the green channel.
struct Spread {
    double x, y;
};
Spread highlightSpread(const std::vector<float>& rgba) {
    double sum = 0.0, sx = 0.0, sy = 0.0;
    const double centre = (kSize - 1) * 0.5;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            const double v = rgba[(y * kSize + x) * 4 + 1];
            sum += v;
            sx += v * (x - centre) * (x - centre);
            sy += v * (y - centre) * (y - centre);
        }
    }
    return {sx / sum, sy / sum};
}

TEST(Anisotropy, TheHighlightFollowsTheTangentAndTheRotation) {
    const Spread along = highlightSpread(test::renderCpu(brushedQuad(brushedMetal(0.0f)), 64, kNeeMis));
    const Spread across = highlightSpread(test::renderCpu(brushedQuad(brushedMetal(kPi / 2)), 64, kNeeMis));
    const Spread reversed = highlightSpread(test::renderCpu(brushedQuad(brushedMetal(kPi)), 64, kNeeMis));
    Material isotropic = brushedMetal(0.0f);
    isotropic.anisotropyStrength = 0.0f;
    const Spread round = highlightSpread(test::renderCpu(brushedQuad(isotropic), 64, kNeeMis));
    EXPECT_GT(along.x, 3.0 * along.y) << along.x << " " << along.y;
    EXPECT_GT(across.y, 3.0 * across.x) << across.x << " " << across.y;
    EXPECT_NEAR(reversed.x / along.x, 1.0, 0.05) << "a direction, not an arrow";
    EXPECT_NEAR(reversed.y / along.y, 1.0, 0.05);
    EXPECT_NEAR(round.x / round.y, 1.0, 0.1);
}

// The direction texture's RG ([-1, 1] tangent space) and B (strength): (0, 1) turns the streak
// as a rotation of 90 degrees does; B = 0 leaves it round.
TEST(Anisotropy, TheTextureGivesDirectionAndStrength) {
    for (const float blue : {1.0f, 0.0f}) {
        Scene scene = brushedQuad(brushedMetal(0.0f));
        scene.materials[0].params.anisotropyTexture.texture =
            addFloatTexture(scene, 2, 2, [&](uint32_t, uint32_t) {
                return Vec4{0.5f, 1.0f, blue, 1.0f};
            });
        const Spread s = highlightSpread(test::renderCpu(scene, 64, kNeeMis));
        if (blue > 0.0f) {
            EXPECT_GT(s.y, 3.0 * s.x) << s.x << " " << s.y;
        } else {
            EXPECT_NEAR(s.x / s.y, 1.0, 0.1);
        }
    }
}

// A smooth glass ball under a white sky of 1: every path leaves it eventually (bar total
// internal reflection past the depth limit), so the image is the sky, dispersion or not, and
// white on average: the wavelength weights tint nothing.
Scene glassBall(float dispersion, Vec3 sky) {
    Scene scene;
    scene.render = {kSize, kSize, 24, 0, 0};
    scene.environment.color = sky;
    scene.camera.position = {0, 0, 4};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.verticalFovDegrees = 30;
    Material glass = test::diffuse(Vec3(1.0f));
    glass.specular = 1.0f;  // diffuse() leaves the specular layer out
    glass.transmission = 1.0f;
    glass.roughness = 0.0f;
    glass.ior = 1.5f;
    glass.dispersion = dispersion;
    addShape(scene, ObjectKind::Sphere, trs({0, 0, 0}), addMaterial(scene, "glass", glass));
    return scene;
}

TEST(Dispersion, AWhiteFurnaceStaysWhite) {
    const std::vector<float> plain = test::renderCpu(glassBall(0.0f, Vec3(1.0f)), 64, kNeeMis);
    const std::vector<float> dispersed = test::renderCpu(glassBall(2.0f, Vec3(1.0f)), 64, kNeeMis);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(meanChannel(dispersed, c), meanChannel(plain, c), 0.01) << "channel " << c;
        EXPECT_NEAR(meanChannel(dispersed, c), 1.0, 0.015) << "channel " << c;
    }
}

// A white light seen through the ball: with dispersion its image has colour fringes; without,
// every sample is grey (white light through white glass), R == B exactly.
TEST(Dispersion, SplitsWhiteLightIntoColours) {
    for (const float dispersion : {0.0f, 3.0f}) {
        Scene scene = glassBall(dispersion, Vec3(0.0f));
        addShape(scene, ObjectKind::Sphere, trs({0.0f, 0.0f, -3.0f}, {0, 0, 0}, Vec3(0.3f)),
                 addMaterial(scene, "lamp", test::emitter(Vec3(5.0f))));
        const std::vector<float> image = test::renderCpu(scene, 64, kNeeMis);
        double difference = 0.0, total = 0.0;
        for (size_t i = 0; i < image.size(); i += 4) {
            difference += std::fabs(image[i] - image[i + 2]);
            total += image[i] + image[i + 2];
        }
        ASSERT_GT(total, 0.0) << "the light is seen through the ball";
        if (dispersion > 0.0f) {
            EXPECT_GT(difference / total, 0.05) << "fringes";
        } else {
            EXPECT_LT(difference / total, 1e-6) << "no fringes without dispersion";
        }
    }
}

}  // namespace
}  // namespace pt
