// The two-level BVH on real imported models gives the same closest hits as brute force,
// for random rays and for rays aimed exactly at vertices and edge midpoints.
#include <gtest/gtest.h>

#include <random>

#include "assets/scene_loader.h"
#include "render/bvh/traversal.h"
#include "render/lights/emitter_sample.h"
#include "render/scene/compile_scene.h"
#include "support/test_paths.h"

namespace pt {
namespace {

struct RayBatch {
    std::vector<Ray> rays;
};

// Random rays through the bounds, plus rays from outside aimed at a vertex or an edge
// midpoint of a random instanced triangle (where a non-watertight test lets rays slip).
RayBatch makeRays(const RenderScene& scene, Vec3 lo, Vec3 hi, size_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const Vec3 extent = hi - lo;
    auto pointIn = [&](float margin) {
        return lo - extent * margin + Vec3{unit(rng), unit(rng), unit(rng)} * extent * (1 + 2 * margin);
    };
    RayBatch batch;
    for (size_t i = 0; i < count; ++i) {
        Ray ray;
        ray.origin = pointIn(0.2f);
        Vec3 target;
        if (i % 3 == 0 || scene.instances.empty()) {
            target = pointIn(0.0f);
        } else {
            const uint32_t inst = uint32_t(rng() % scene.instances.count);
            const BlasRef& blas = scene.blases[scene.instances[inst].blas];
            if (blas.kind != GeometryKind::Triangles || blas.primitiveCount == 0) continue;
            const WorldTriangle tri = worldTriangle(scene, inst, uint32_t(rng() % blas.primitiveCount));
            target = i % 3 == 1 ? tri.p0 : (tri.p0 + tri.p1) * 0.5f;
        }
        ray.direction = target - ray.origin;
        if (lengthSquared(ray.direction) == 0.0f) continue;
        ray.direction = normalize(ray.direction);
        batch.rays.push_back(ray);
    }
    return batch;
}

void expectBvhMatchesBruteForce(const std::string& asset, size_t rayCount) {
    PT_REQUIRE_SHARED_ASSET(asset);
    const LoadResult loaded = loadScene(test::sharedAsset(asset));
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    const CompiledScene bvh = compileRenderScene(*loaded.scene);
    CompileOptions bruteOptions;
    bruteOptions.bruteForce = true;
    bruteOptions.bruteForceBudget = ~0ull;
    const CompiledScene brute = compileRenderScene(*loaded.scene, bruteOptions);
    Vec3 lo, hi;
    loaded.scene->worldBounds(lo, hi);
    const RenderScene bvhView = bvh.view(), bruteView = brute.view();
    const RayBatch batch = makeRays(bvhView, lo, hi, rayCount, 1234);
    size_t hits = 0, mismatches = 0;
    for (const Ray& ray : batch.rays) {
        Hit a{}, b{};
        const bool hitA = intersectClosest(bvhView, ray, a);
        const bool hitB = intersectClosest(bruteView, ray, b);
        EXPECT_EQ(intersectAny(bvhView, ray), hitB);
        if (hitA != hitB || (hitA && a.t != b.t)) {
            // Equal t on two primitives (shared edges) may pick either; any other difference is a bug.
            if (++mismatches <= 5) {
                ADD_FAILURE() << asset << ": BVH " << hitA << " t=" << a.t << " (instance " << a.instance
                              << ", primitive " << a.primitive << ") vs brute force " << hitB << " t=" << b.t
                              << " (instance " << b.instance << ", primitive " << b.primitive << ")";
            }
        }
        hits += hitB;
    }
    EXPECT_EQ(mismatches, 0u) << asset;
    EXPECT_GT(hits, batch.rays.size() / 4) << asset << ": too few rays hit to test anything";
}

TEST(ImportedBvh, CornellBoxGlbMatchesBruteForce) { expectBvhMatchesBruteForce("CornellBox/CornellBox.glb", 200000); }
TEST(ImportedBvh, CornellBoxObjMatchesBruteForce) { expectBvhMatchesBruteForce("CornellBoxObj/cornell_box.obj", 30000); }
TEST(ImportedBvh, DepthOfFieldExampleMatchesBruteForce) {
    expectBvhMatchesBruteForce("DepthOfFieldExample/DepthOfFieldExample.glb", 20000);
}
TEST(ImportedBvh, FoxMatchesBruteForce) { expectBvhMatchesBruteForce("Fox/Fox.glb", 50000); }
TEST(ImportedBvh, BalloonMatchesBruteForce) { expectBvhMatchesBruteForce("Balloon/scene.gltf", 10000); }

}  // namespace
}  // namespace pt
