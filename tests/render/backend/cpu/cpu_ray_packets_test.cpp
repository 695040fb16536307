// The CPU backend's 8-ray packets of camera rays (IntegratorToggles::rayPackets,
// render/bvh/packet_traversal.h): the image, its variance and the rays counted are those of
// one ray at a time, bit for bit, on a scene whose instances all merge into the world-space
// BLAS, on the same instances under a TLAS, and on one mesh through its instance transform, at
// a size that leaves tiles with partial packets, and through a wide lens, whose blocks of rays
// often point too many ways for a packet; traceRays' closest and shadow hits in packets answer
// as one at a time, merged and under a TLAS.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "render/backend/cpu/cpu_backend.h"
#include "render/bvh/bvh_test_util.h"
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

// traceRays' hits of `rays` (closest, or any: Hit::instance 0 where occluded), with packets on
// or off.
std::vector<Hit> traced(const Scene& scene, const std::vector<Ray>& rays, bool anyHit, bool packets,
                        bool merge) {
    IntegratorToggles toggles;
    toggles.rayPackets = packets;
    toggles.mergeInstances = merge;
    CpuBackend backend;
    backend.setToggles(toggles);
    backend.sync(scene, SceneChanges::All, {});
    std::vector<Hit> hits;
    backend.traceRays(rays, anyHit, 1, &hits);
    return hits;
}

std::vector<bool> occlusion(const Scene& scene, const std::vector<Ray>& rays, bool packets, bool merge) {
    std::vector<bool> occluded;
    for (const Hit& hit : traced(scene, rays, true, packets, merge)) occluded.push_back(hit.valid());
    return occluded;
}

// A wide lens: neighbouring pixels' rays leave from points of the lens up to 4 apart toward a
// focus about 4 away (up to about 53 degrees between them), so many of their blocks point too
// many ways for a packet (raysCoherent) and go one at a time, beside blocks that go as packets.
TEST(CpuRayPackets, AWideLensRendersBitForBitAsOneRayAtATime) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Scene scene = roomCorner();
    scene.camera.apertureRadius = 2.0f;
    expectPacketsChangeNothing(scene);
}

TEST(CpuRayPackets, RaysAreCoherentWhereTheyPointAboutOneWay) {
    const Vec3 forward(0.1f, -0.2f, -1.0f);
    std::vector<Ray> rays(kRayPacketSize, Ray{Vec3(0.0f), forward, kInf});
    for (uint32_t k = 0; k < kRayPacketSize; ++k) {
        rays[k].direction = (forward + Vec3(0.02f * float(k % 4), 0.02f * float(k / 4), 0.0f)) * float(k + 1);
    }
    EXPECT_TRUE(raysCoherent(rays.data(), kRayPacketSize)) << "a camera's neighbouring pixels, any lengths";
    EXPECT_TRUE(raysCoherent(rays.data(), 1));
    std::vector<Ray> turned = rays;
    turned[5].direction = Vec3(0.1f, -0.2f + 0.7f, -1.0f);  // about 34 degrees off the first
    EXPECT_FALSE(raysCoherent(turned.data(), kRayPacketSize));
    EXPECT_TRUE(raysCoherent(turned.data(), 5)) << "the rays before it";
    turned[5].direction = Vec3(0.1f, -0.2f + 0.3f, -1.0f);  // about 17 degrees off
    EXPECT_TRUE(raysCoherent(turned.data(), kRayPacketSize));
    std::vector<Ray> opposite = rays;
    opposite[7].direction = forward * -1.0f;
    EXPECT_FALSE(raysCoherent(opposite.data(), kRayPacketSize));
}

// Closest hits by traceRays with packets on: coherent blocks of eight walk as packets, blocks
// that point every way one ray at a time, and every hit is the single ray's.
TEST(CpuRayPackets, ClosestHitsOfTraceRaysAnswerAsOneAtATime) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    const Scene scene = roomCorner();
    std::vector<Ray> rays;
    test::Rng rng(12);
    for (int block = 0; block < 40; ++block) {
        const Vec3 origin(rng.uniform(-1.0f, 1.0f), rng.uniform(-0.5f, 1.0f), rng.uniform(1.0f, 3.0f));
        for (uint32_t k = 0; k < kRayPacketSize; ++k) {
            const Vec3 coherent(0.05f * float(k % 4) - 0.1f, 0.05f * float(k / 4) - 0.3f, -1.0f);
            const Vec3 any(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f));
            rays.push_back({origin, block % 2 ? coherent : any, kInf});
        }
    }
    for (const bool merge : {true, false}) {
        SCOPED_TRACE(merge ? "merged" : "under a TLAS");
        const std::vector<Hit> hits[2] = {traced(scene, rays, false, false, merge),
                                          traced(scene, rays, false, true, merge)};
        ASSERT_EQ(hits[0].size(), rays.size());
        ASSERT_EQ(hits[1].size(), rays.size());
        size_t differ = 0, valid = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            const Hit& a = hits[0][i];
            const Hit& b = hits[1][i];
            valid += a.valid();
            differ += a.valid() != b.valid() ||
                      (a.valid() && (a.t != b.t || a.primitive != b.primitive || a.instance != b.instance));
        }
        EXPECT_EQ(differ, 0u);
        EXPECT_GT(valid, rays.size() / 2) << "most rays should hit the room";
    }
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
