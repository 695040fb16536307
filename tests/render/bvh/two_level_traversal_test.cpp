// Two-level traversal (render/bvh/tlas_traversal.h): instances with rotations, non-uniform and
// negative scales, shared BLASes and sphere BLASes, compiled by compileRenderScene; closest
// hits equal a brute-force loop over instances, and t is in the world ray's parametrisation.
#include <gtest/gtest.h>

#include "render/bvh/bvh_test_util.h"
#include "render/bvh/traversal.h"

namespace pt {
namespace {

using test::Rng;
using test::SoupKind;

Vec4 randomRotation(Rng& rng) {
    const Vec3 axis = rng.unitVector();
    const float half = rng.uniform(0.0f, kPi);
    const float s = std::sin(half);
    return {axis.x * s, axis.y * s, axis.z * s, std::cos(half)};
}

// Meshes: a soup, an icosphere, a sphere BLAS of many spheres, one unit sphere.
// Instances: each mesh several times, randomly rotated, scaled (some negative) and placed.
CompiledScene makeScene(Rng& rng, std::vector<test::InstanceSpec>& specs, bool merge = false,
                        test::Layout layout = test::Layout::Binary) {
    std::vector<Mesh> meshes;
    meshes.push_back(test::makeSoup(SoupKind::Clustered, 1000, rng));
    meshes.push_back(test::makeIcosphere(2));
    std::vector<Vec4> spheres;
    for (int i = 0; i < 200; ++i) {
        const Vec3 c = rng.inBox(Vec3(-1.0f), Vec3(1.0f));
        spheres.push_back({c.x, c.y, c.z, rng.uniform(0.01f, 0.15f)});
    }
    meshes.push_back(test::makeSphereMesh(spheres));
    meshes.push_back(test::makeSphereMesh({{0, 0, 0, 1}}));
    for (uint32_t i = 0; i < 24; ++i) {
        Vec3 scale{rng.uniform(0.2f, 1.5f), rng.uniform(0.2f, 1.5f), rng.uniform(0.2f, 1.5f)};
        if (i % 3 == 0) scale.x = -scale.x;     // mirrored
        if (i % 8 == 1) scale = Vec3(scale.y);  // uniform
        const Affine3 toWorld = translationTransform(rng.inBox(Vec3(-4.0f), Vec3(4.0f))) *
                                rotationTransform(randomRotation(rng)) * scaleTransform(scale);
        specs.push_back({i % 4, toWorld});
    }
    CompileOptions options = test::layoutOptions(layout);
    options.mergeSmallInstances = merge;  // the two-level walk on its own; merging is tested below
    return test::compileTestScene(std::move(meshes), specs, options);
}

class TwoLevelLayouts : public test::LayoutTest {};
INSTANTIATE_TEST_SUITE_P(Layouts, TwoLevelLayouts, ::testing::ValuesIn(test::kLayouts), test::layoutTestName);

TEST_P(TwoLevelLayouts, MatchesBruteForceOverInstances) {
    Rng rng(41);
    std::vector<test::InstanceSpec> specs;
    const CompiledScene compiled = makeScene(rng, specs, false, GetParam());
    const RenderScene scene = compiled.view();
    ASSERT_EQ(scene.instances.size(), 24u);
    int failures = 0;
    uint32_t hits = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray = test::randomRay(rng, Vec3(-6.0f), Vec3(6.0f));
        if (i % 4 == 3) ray.tMax = rng.uniform(0.0f, 1.0f);
        hits += test::expectBvhMatchesBruteForce(scene, ray, failures);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(hits, 4000u);
}

// Coincident instances: a soup placed three times at one place (instances 2, 3 and 4), and a
// wider mesh that holds the same triangles too, there (1) and elsewhere (0). Every hit on the
// soup ties in t between 1 to 4; it goes to the lowest instance holding it (tlas_traversal.h),
// as brute force's in-order test has it, in every layout, whatever order the walk meets the
// instances in; and with the merged BLAS (copies of 2 to 4 in world space), which must give
// its hit back to 1.
TEST_P(TwoLevelLayouts, TiesBetweenInstancesGoToTheLowerInstance) {
    Rng rng(43);
    const Mesh soup = test::makeSoup(SoupKind::Clustered, 300, rng);
    // The soup's triangles, and beyond the rays' reach enough more that its two instances are
    // not merged (2 x 33,068 copies would pass merged_geometry.h's limit).
    Mesh wider = soup;
    const Mesh filler = test::makeSoup(SoupKind::Uniform, 1u << 15, rng);
    const uint32_t base = uint32_t(wider.positions.size());
    for (const Vec3& p : filler.positions) wider.positions.push_back(p * 0.5f + Vec3(20.0f, 0.0f, 0.0f));
    for (const uint32_t index : filler.indices) wider.indices.push_back(base + index);
    const std::vector<test::InstanceSpec> specs = {
        {1, translationTransform(Vec3(3.0f, 0.0f, 0.0f))},  // the soup's triangles at x + 3
        {1, Affine3{}},  // the lowest to hold the soup's triangles; never merged
        {0, Affine3{}},  // 2 to 4: merged where merging is on, so the merged BLAS ties with 1
        {0, Affine3{}},
        {0, Affine3{}},
    };
    for (const bool merge : {false, true}) {
        CompileOptions options = test::layoutOptions(GetParam());
        options.mergeSmallInstances = merge;
        const CompiledScene compiled = test::compileTestScene({soup, wider}, specs, options);
        const RenderScene scene = compiled.view();
        ASSERT_GT(compiled.tlasInstanceIndices.size(), 1u);
        ASSERT_EQ(compiled.merged.active(), merge);
        ASSERT_FALSE(compiled.instances[1].tracedInWorldSpace);
        // The merged BLAS's triangles in instance order, which its tie rule needs
        // (merged_geometry.h): its lower primitive is then the lower instance.
        for (size_t t = 1; t < compiled.mergedTriangles.size(); ++t)
            ASSERT_LE(compiled.mergedTriangles[t - 1].instance, compiled.mergedTriangles[t].instance);
        RenderScene bruteForce = scene;
        bruteForce.bruteForce = 1;
        uint32_t hits = 0, onLowest = 0, differ = 0;
        for (int i = 0; i < 1000; ++i) {
            const Ray ray = test::rayAtTriangle(rng, soup, Vec3(-1.3f), Vec3(1.3f));
            Hit hit;
            const bool found = intersectClosest(scene, ray, hit);
            hits += found;
            onLowest += found && hit.instance == 1;
            if (i % 10 != 0) continue;  // brute force tests all 67,000 triangles: one ray in ten
            Hit expected;
            intersectClosest(bruteForce, ray, expected);
            differ += found != expected.valid() ||
                      (found &&
                       (hit.t != expected.t || hit.instance != expected.instance ||
                        hit.primitive != expected.primitive || hit.u != expected.u || hit.v != expected.v));
        }
        EXPECT_EQ(differ, 0u) << (merge ? "merged" : "instances");
        // A ray at a triangle of the soup meets the soup first (that triangle or one before it),
        // which instances 1 to 4 all hold (the soup's triangles are the wider mesh's first).
        EXPECT_GT(hits, 900u);
        EXPECT_EQ(onLowest, hits) << (merge ? "merged" : "instances");
    }
}

// The unit-sphere instances: world hit point o + t d lies on the transformed sphere, whatever
// the length of d (t is not renormalised at the instance).
TEST(TwoLevelTraversal, HitDistanceIsInWorldUnits) {
    Rng rng(43);
    std::vector<test::InstanceSpec> specs;
    const CompiledScene compiled = makeScene(rng, specs);
    const RenderScene scene = compiled.view();
    uint32_t checked = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray = test::randomRay(rng, Vec3(-6.0f), Vec3(6.0f));
        ray.direction = ray.direction * rng.uniform(0.1f, 10.0f);
        Hit hit;
        if (!intersectClosest(scene, ray, hit)) continue;
        ASSERT_LT(hit.t, ray.tMax);
        const RenderInstance& inst = scene.instances[hit.instance];
        if (inst.blas != 3) continue;
        const Vec3 local = inst.worldToObject.transformPoint(ray.origin + ray.direction * hit.t);
        EXPECT_NEAR(length(local), 1.0f, 2e-4f);
        ++checked;
    }
    EXPECT_GT(checked, 100u);
}

TEST(TwoLevelTraversal, SharedEdgesAcrossMirroredInstancesStayWatertight) {
    // A mirrored icosphere: negative determinant flips the winding; two-sided tests ignore it.
    Rng rng(47);
    const Affine3 mirror = rotationTransform(randomRotation(rng)) * scaleTransform({-1.0f, 2.0f, 0.7f});
    const CompiledScene compiled = test::compileTestScene({test::makeIcosphere(3)}, {{0, mirror}});
    const RenderScene scene = compiled.view();
    EXPECT_EQ(scene.instances[0].flipsWinding, 1u);
    uint32_t slipped = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3 local = rng.unitVector() * (0.9f * rng.uniform());
        const Ray ray{mirror.transformPoint(local), mirror.transformVector(rng.unitVector()), kInf};
        Hit hit;
        if (!intersectClosest(scene, ray, hit)) ++slipped;
    }
    EXPECT_EQ(slipped, 0u);
}

// Merged small instances (render/compile/merged_geometry.h): the same scene with its triangle
// instances copied into one world-space BLAS hits what the two-level walk hits. Hits come back
// as the instance and mesh-local triangle they copy; t differs by the rounding of a world-space
// test (relative 1e-5 allowed); grazing rays along shared edges may go either way (a few).
TEST(TwoLevelTraversal, MergedInstancesHitWhatTheirInstancesHit) {
    Rng rng(41), sameRng(41);
    std::vector<test::InstanceSpec> specs, sameSpecs;
    const CompiledScene instanced = makeScene(rng, specs);
    const CompiledScene merged = makeScene(sameRng, sameSpecs, true);
    ASSERT_TRUE(merged.merged.active());
    size_t mergedInstances = 0;
    for (const RenderInstance& inst : merged.instances) mergedInstances += inst.tracedInWorldSpace;
    EXPECT_GE(mergedInstances, 6u) << "the soup and the icosphere instances";
    EXPECT_LT(merged.tlasInstanceIndices.size(), instanced.tlasInstanceIndices.size());
    const RenderScene a = instanced.view(), b = merged.view();
    int disagreements = 0, hits = 0, mergedHits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = test::randomRay(rng, Vec3(-6.0f), Vec3(6.0f));
        Hit ha, hb;
        const bool hitA = intersectClosest(a, ray, ha), hitB = intersectClosest(b, ray, hb);
        EXPECT_EQ(intersectAny(b, ray), hitB);
        hits += hitA;
        if (hitB) mergedHits += b.instances[hb.instance].tracedInWorldSpace;
        const bool same =
            hitA == hitB && (!hitA || (std::abs(ha.t - hb.t) <= 1e-5f * ha.t && ha.instance == hb.instance &&
                                       ha.primitive == hb.primitive));
        disagreements += !same;
    }
    EXPECT_GT(hits, 4000);
    EXPECT_GT(mergedHits, 1000) << "rays reach the merged BLAS";
    EXPECT_LE(disagreements, 10) << "of 20000 rays";
}

}  // namespace
}  // namespace pt
