// The environment as a light: a sky with a sun 1e5 times brighter than the rest, on one
// texel, renders without NaN or Inf and converges to the irradiance a quadrature of the
// same radiance gives (MIS weights between environment sampling and BSDF sampling finite).
#include <gtest/gtest.h>

#include <cmath>

#include "render/compile/compile_scene.h"
#include "render/integrator/path_tracer.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::addFloatTexture;
using test::floorPointScene;
using test::meanChannel;

// Irradiance at an up-facing point: the integral of L cos(theta) over the upper hemisphere,
// on a grid of the equirect square fine enough to resolve one texel (dw = 2 pi^2 sin dv du).
double hemisphereIrradiance(const RenderScene& view, int channel) {
    constexpr int kU = 4096, kV = 2048;
    double sum = 0.0;
    for (int j = 0; j < kV / 2; ++j) {
        const double v = (j + 0.5) / kV, theta = v * kPi;
        for (int i = 0; i < kU; ++i) {
            const Vec3 d =
                equirectToDirection({float((i + 0.5) / kU), float(v)}, view.environment.rotationRadians);
            sum += environmentRadiance(view, d)[channel] * std::cos(theta) * std::sin(theta);
        }
    }
    return sum * 2 * kPi * kPi / (double(kU) * kV);
}

TEST(EnvironmentLight, TinySunConvergesWithoutNonFiniteSamples) {
    Scene scene = floorPointScene(0.7f);
    scene.environment.texture = addFloatTexture(scene, 64, 32, [](uint32_t x, uint32_t y) {
        const float l = x == 40 && y == 9 ? 0.5e5f : 0.5f;
        return Vec4{l, 0.9f * l, 0.8f * l, 1};
    });
    scene.environment.rotationDegrees = 20.0f;
    const CompiledScene compiled = compileRenderScene(scene);
    ASSERT_TRUE(compiled.stats.environmentSampled);
    const double expected = 0.7 / kPi * hemisphereIrradiance(compiled.view(), 1);

    CpuBackend backend;
    backend.sync(scene, SceneChanges::All, {});
    backend.render(1024);
    EXPECT_EQ(backend.stats().nonfiniteSamples, 0u);
    std::vector<float> image;
    backend.readBeauty(image);
    for (float v : image) ASSERT_TRUE(std::isfinite(v));
    EXPECT_NEAR(meanChannel(image, 1) / expected, 1.0, 0.02) << meanChannel(image, 1) << " vs " << expected;

    // BSDF sampling alone rarely finds the sun; it stays finite and unbiased, only noisy.
    backend.setToggles({false, false, true, false});
    backend.render(64);
    EXPECT_EQ(backend.stats().nonfiniteSamples, 0u);
}

}  // namespace
}  // namespace pt
