// The CPU backend's 8-ray packets of camera rays (IntegratorToggles::rayPackets,
// render/bvh/packet_traversal.h): the image, its variance and the rays counted are those of
// one ray at a time, bit for bit, on a scene whose instances all merge into the world-space
// BLAS, on the same instances under a TLAS, and on one mesh through its instance transform, at
// a size that leaves tiles with partial packets; and traceRays' shadow rays in packets answer as
// one at a time, merged and under a TLAS.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "render/backend/cpu/cpu_backend.h"
#include "render/bvh/packet_traversal.h"
#include "render/bvh/wide_walk_simd.h"
#include "render/compile/compile_scene.h"
#include "support/render_cpu.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

struct Rendered {
    std::vector<float> beauty, variance;
    uint64_t rays = 0;
};

Rendered render(const Scene& scene, bool packets, bool merge) {
    IntegratorToggles toggles;
    toggles.rayPackets = packets;
    toggles.mergeInstances = merge;
    CpuBackend backend;
    backend.setToggles(toggles);
    backend.setAovs(aovBit(Aov::Variance));  // per-sample bookkeeping, not a path AOV
    backend.sync(scene, SceneChanges::All, {});
    backend.render(3);
    backend.render(2);  // a second call goes on from sample 3
    return {test::beautyOf(backend), test::aovOf(backend, Aov::Variance), backend.stats().rays};
}

// A room corner: floor, back wall, a mirror box and a glossy box under a lamp, at 53 x 21:
// tiles of 13-14 by 10-11 pixels, so 4 x 2 blocks at their edges hold fewer than eight.
Scene roomCorner() {
    Scene scene;
    scene.render = {53, 21, 4, 1, 0};
    scene.camera.position = {0, 0.6f, 4};
    scene.camera.lookAt = {0, 0, 0};
    const uint32_t white = test::addMaterial(scene, "white", test::diffuse({0.7f, 0.7f, 0.7f}));
    Material mirror = test::diffuse({0.9f, 0.9f, 0.9f});
    mirror.metallic = 1.0f;
    mirror.roughness = 0.0f;
    const uint32_t shiny = test::addMaterial(scene, "mirror", mirror);
    const uint32_t lamp = test::addMaterial(scene, "lamp", test::emitter({4, 4, 4}));
    test::addShape(scene, ObjectKind::Quad, test::trs({0, -1, 0}, {0, 0, 0}, {3, 1, 3}), white, "floor");
    test::addShape(scene, ObjectKind::Quad, test::trs({0, 0, -1}, {90, 0, 0}, {3, 1, 3}), white, "wall");
    test::addShape(scene, ObjectKind::Box, test::trs({-0.5f, -0.5f, 0}, {0, 30, 0}, {0.4f, 0.5f, 0.4f}),
                   shiny, "mirror box");
    test::addShape(scene, ObjectKind::Box, test::trs({0.6f, -0.7f, 0.3f}, {0, -20, 0}, {0.3f, 0.3f, 0.3f}),
                   white, "white box");
    test::addShape(scene, ObjectKind::Quad, test::trs({0, 1.5f, 0}, {180, 0, 0}, {0.8f, 1, 0.8f}), lamp,
                   "lamp");
    test::addLight(scene, LightType::Point, {1, 1, 1}, 3.0f, {1, 1, 2});
    return scene;
}

void expectPacketsChangeNothing(const Scene& scene, bool merge = true) {
    CompileOptions options;
    options.wideBvh = true;
    options.mergeSmallInstances = merge;
    ASSERT_TRUE(packetWalkApplies(compileRenderScene(scene, options).view())) << "the packets should apply";
    const Rendered packets = render(scene, true, merge), single = render(scene, false, merge);
    EXPECT_EQ(packets.beauty, single.beauty);
    EXPECT_EQ(packets.variance, single.variance);
    EXPECT_EQ(packets.rays, single.rays);
    EXPECT_GT(test::meanChannel(single.beauty, 1), 0.0) << "something should be lit";
}

TEST(CpuRayPackets, MergedInstancesRenderBitForBitAsOneRayAtATime) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    expectPacketsChangeNothing(roomCorner());
}

TEST(CpuRayPackets, InstancesUnderATlasRenderBitForBitAsOneRayAtATime) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    expectPacketsChangeNothing(roomCorner(), false);
}

TEST(CpuRayPackets, OneTransformedMeshRendersBitForBitAsOneRayAtATime) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    // The white box alone: one instance, rays taken into its object space.
    Scene scene = roomCorner();
    const auto box = std::find_if(scene.instances.begin(), scene.instances.end(),
                                  [](const Instance& i) { return i.name == "white box"; });
    ASSERT_NE(box, scene.instances.end());
    scene.instances = {*box};
    expectPacketsChangeNothing(scene);
}

// Occlusion of each ray by traceRays (Hit::instance 0: occluded), with packets on or off.
std::vector<bool> occlusion(const Scene& scene, const std::vector<Ray>& rays, bool packets, bool merge) {
    IntegratorToggles toggles;
    toggles.rayPackets = packets;
    toggles.mergeInstances = merge;
    CpuBackend backend;
    backend.setToggles(toggles);
    backend.sync(scene, SceneChanges::All, {});
    std::vector<Hit> hits;
    backend.traceRays(rays, true, 1, &hits);
    std::vector<bool> occluded;
    for (const Hit& hit : hits) occluded.push_back(hit.valid());
    return occluded;
}

TEST(CpuRayPackets, ShadowRaysInPacketsAnswerAsOneAtATime) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    const Scene scene = roomCorner();
    // Segments from a grid on the floor to the point light: the boxes shadow some of them. 101
    // rays, so the last packet holds five.
    std::vector<Ray> rays;
    const Vec3 light(1, 1, 2);
    for (int i = 0; i < 101; ++i) {
        const Vec3 origin(-1.5f + 0.3f * float(i % 11), -0.999f, -0.9f + 0.3f * float(i / 11));
        rays.push_back({origin, light - origin, 1.0f});
    }
    for (const bool merge : {true, false}) {
        SCOPED_TRACE(merge ? "merged" : "under a TLAS");
        const std::vector<bool> packets = occlusion(scene, rays, true, merge);
        EXPECT_EQ(packets, occlusion(scene, rays, false, merge));
        const auto shadowed = std::count(packets.begin(), packets.end(), true);
        EXPECT_GT(shadowed, 0) << "some rays should be shadowed";
        EXPECT_LT(shadowed, std::ptrdiff_t(rays.size())) << "some rays should reach the light";
    }
}

}  // namespace
}  // namespace pt
