// Backend::setInterruptFlag on the CPU backend: a raised flag stops render() within a tile and
// leaves an empty accumulation, never a torn one (a pass that reached some pixels only), so
// what is rendered after it equals what a fresh backend renders.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <thread>

#include "render/backend/backend.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

// A diffuse quad under a point light, 64x64.
Scene litQuad() {
    Scene scene;
    scene.render = {64, 64, 4, 1, 0};
    scene.camera.position = {0, 2, 0};
    scene.camera.up = {0, 0, -1};
    const uint32_t m = test::addMaterial(scene, "quad", test::diffuse({0.7f, 0.6f, 0.5f}));
    test::addShape(scene, ObjectKind::Quad, test::trs({0, 0, 0}), m, "quad");
    test::addLight(scene, LightType::Point, {1, 1, 1}, 5.0f, {0, 1, 0});
    scene.environment.color = {0.2f, 0.2f, 0.3f};
    return scene;
}

TEST(RenderInterrupt, ARaisedFlagStopsThePassInFlightAndLeavesNoTornSamples) {
    const Scene scene = litQuad();
    std::unique_ptr<Backend> backend = createBackend("cpu");
    std::atomic<bool> interrupt{false};
    backend->setInterruptFlag(&interrupt);
    backend->setAovs(aovBit(Aov::Albedo) | aovBit(Aov::Variance));
    backend->sync(scene, SceneChanges::All, {});
    backend->render(2);
    ASSERT_EQ(backend->stats().samplesPerPixel, 2u);

    // 64x64 pixels x 10^7 samples: hours, unless the flag stops it.
    auto pass = std::async(std::launch::async, [&] { backend->render(10'000'000); });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    interrupt = true;
    if (pass.wait_for(std::chrono::seconds(120)) != std::future_status::ready) {
        std::fprintf(stderr, "render() went on with the interrupt flag up\n");
        std::abort();  // the pass would hold the test process for hours
    }
    EXPECT_EQ(backend->stats().samplesPerPixel, 0u);
    EXPECT_EQ(backend->stats().rays, 0u);
    for (const float v : test::beautyOf(*backend))
        ASSERT_TRUE(v == 0.0f || v == 1.0f) << "a torn pass left samples";

    // While the flag is up nothing renders; once lowered the accumulation starts afresh.
    backend->render(1);
    EXPECT_EQ(backend->stats().samplesPerPixel, 0u);
    interrupt = false;
    backend->render(3);
    std::unique_ptr<Backend> fresh = createBackend("cpu");
    fresh->setAovs(aovBit(Aov::Albedo) | aovBit(Aov::Variance));
    fresh->sync(scene, SceneChanges::All, {});
    fresh->render(3);
    EXPECT_EQ(test::beautyOf(*backend), test::beautyOf(*fresh));
    EXPECT_EQ(test::aovOf(*backend, Aov::Variance), test::aovOf(*fresh, Aov::Variance));
}

}  // namespace
}  // namespace pt
