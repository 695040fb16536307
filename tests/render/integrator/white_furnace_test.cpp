// White furnace: lossless diffuse objects (albedo 1, no specular layer) inside a uniform
// environment of radiance L look exactly like the environment, however light bounces
// between them. Run with NEE+MIS on and with environment importance sampling (a constant
// image) as well as with a constant colour.
#include <gtest/gtest.h>

#include "render/integrator/path_tracer.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addFloatTexture;
using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::trs;

// A sphere resting on a floor, with a box beside it: light interreflects between all three.
Scene furnace() {
    Scene scene;
    scene.render = {40, 30, 128, 0, 0};
    scene.camera.position = {0.5f, 1.5f, 4.0f};
    scene.camera.lookAt = {0, 0.3f, 0};
    scene.camera.verticalFovDegrees = 50;
    const uint32_t white = addMaterial(scene, "white", diffuse(Vec3(1.0f)));
    addShape(scene, ObjectKind::Quad, trs({0, 0, 0}, {0, 0, 0}, {2, 1, 2}), white);
    addShape(scene, ObjectKind::Sphere, trs({-0.5f, 0.6f, 0}, {0, 0, 0}, Vec3(0.6f)), white);
    addShape(scene, ObjectKind::Box, trs({0.7f, 0.5f, -0.2f}, {0, 30, 0}, Vec3(0.5f)), white);
    return scene;
}

void expectFurnace(const Scene& scene, float sky, const char* what) {
    const std::vector<float> image = test::renderCpu(scene, 64);
    for (int c = 0; c < 3; ++c) {
        const double mean = test::meanChannel(image, c);
        EXPECT_NEAR(mean / sky, 1.0, 0.005) << what << " channel " << c << ": " << mean;
    }
}

TEST(WhiteFurnace, ConstantColourEnvironment) {
    Scene scene = furnace();
    scene.environment.color = Vec3(0.6f);
    expectFurnace(scene, 0.6f, "constant colour");
}

TEST(WhiteFurnace, ImportanceSampledConstantImage) {
    Scene scene = furnace();
    scene.environment.texture = addFloatTexture(scene, 32, 16, [](uint32_t, uint32_t) {
        return Vec4{0.5f, 0.5f, 0.5f, 1};
    });
    scene.environment.intensity = 1.2f;
    scene.environment.rotationDegrees = 40.0f;
    expectFurnace(scene, 0.6f, "constant image");
}

}  // namespace
}  // namespace pt
