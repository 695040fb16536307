// Closest- and any-hit traversal (render/bvh/traversal.h) against brute force over one mesh:
// random soups of every kind, axis-aligned rays, finite tMax, empty scenes, stats; each for the
// binary BVH and for the CPU's 8-wide form of it.
#include "render/bvh/traversal.h"

#include <gtest/gtest.h>

#include "render/bvh/bvh_test_util.h"

namespace pt {
namespace {

using test::Rng;
using test::SoupKind;

constexpr SoupKind kKinds[] = {SoupKind::Uniform, SoupKind::Clustered, SoupKind::Needles,
                               SoupKind::CoincidentCentroids};

// rays x triangles per kind: many rays through small soups, fewer through large ones.
class Traversal : public test::LayoutTest {};
INSTANTIATE_TEST_SUITE_P(Layouts, Traversal, ::testing::ValuesIn(test::kLayouts), test::layoutTestName);

void compareSoups(uint32_t triangles, uint32_t rays, uint32_t seed, test::Layout layout) {
    Rng rng(seed);
    for (SoupKind kind : kKinds) {
        SCOPED_TRACE(test::soupName(kind));
        const Mesh mesh = test::makeSoup(kind, triangles, rng);
        const CompiledScene compiled = test::compileSingleMesh(mesh, layout);
        const RenderScene scene = compiled.view();
        int failures = 0;
        uint32_t hits = 0;
        for (uint32_t i = 0; i < rays; ++i) {
            const Ray ray = i % 2 ? test::randomRay(rng, Vec3(-1.2f), Vec3(1.2f))
                                  : test::rayAtTriangle(rng, mesh, Vec3(-1.2f), Vec3(1.2f));
            hits += test::expectBvhMatchesBruteForce(scene, ray, failures);
        }
        EXPECT_EQ(failures, 0);
        EXPECT_GT(hits, rays / 3) << "the rays should hit often enough to test something";
    }
}

TEST_P(Traversal, SmallSoupsMatchBruteForce) { compareSoups(128, 250000, 1, GetParam()); }  // 1M rays
TEST_P(Traversal, LargeSoupsMatchBruteForce) { compareSoups(20000, 2500, 2, GetParam()); }

TEST_P(Traversal, FiniteTMaxMatchesBruteForce) {
    Rng rng(3);
    const Mesh mesh = test::makeSoup(SoupKind::Uniform, 2000, rng);
    const CompiledScene compiled = test::compileSingleMesh(mesh, GetParam());
    const RenderScene scene = compiled.view();
    int failures = 0;
    for (int i = 0; i < 25000; ++i) {
        Ray ray = test::rayAtTriangle(rng, mesh, Vec3(-1.2f), Vec3(1.2f));
        ray.tMax = rng.uniform(0.0f, 1.5f);  // segments, as for shadow rays
        test::expectBvhMatchesBruteForce(scene, ray, failures);
    }
    EXPECT_EQ(failures, 0);
}

// Direction components of exactly zero: 1/0 must not turn into 0 * inf = NaN in the slab test,
// including for origins exactly on box faces (vertices on a grid of 1/8).
TEST_P(Traversal, AxisAlignedRaysMatchBruteForce) {
    Rng rng(4);
    Mesh mesh;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 c{std::round(rng.uniform(-8, 8)) / 8, std::round(rng.uniform(-8, 8)) / 8,
                     std::round(rng.uniform(-8, 8)) / 8};
        const Vec3 p[3] = {c, c + Vec3{0.125f, 0, 0}, c + Vec3{0, 0.125f, 0.125f}};
        for (const Vec3& v : p) {
            mesh.indices.push_back(uint32_t(mesh.positions.size()));
            mesh.positions.push_back(v);
        }
    }
    const CompiledScene compiled = test::compileSingleMesh(mesh, GetParam());
    const RenderScene scene = compiled.view();
    int failures = 0;
    uint32_t hits = 0;
    const Vec3 dirs[] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 0}, {0, -1, 1}, {-1, 0, -1}, {-0.0f, 0, 1}};
    for (int i = 0; i < 30000; ++i) {
        const Vec3 o{std::round(rng.uniform(-9, 9)) / 8, std::round(rng.uniform(-9, 9)) / 8,
                     std::round(rng.uniform(-9, 9)) / 8};
        hits += test::expectBvhMatchesBruteForce(scene, Ray{o, dirs[i % 7], kInf}, failures);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(hits, 1000u);
}

// Every triangle twice (the copy's index n higher): each hit is an exact tie, which brute force
// gives to the lower index, and so must every walk, whatever order it meets the leaves in.
TEST_P(Traversal, TiesGoToTheLowerPrimitive) {
    Rng rng(15);
    Mesh mesh = test::makeSoup(SoupKind::Uniform, 3000, rng);
    const size_t indices = mesh.indices.size();
    for (size_t i = 0; i < indices; ++i) mesh.indices.push_back(mesh.indices[i]);
    const CompiledScene compiled = test::compileSingleMesh(mesh, GetParam());
    RenderScene bvh = compiled.view(), brute = compiled.view();
    brute.bruteForce = 1;
    uint32_t hits = 0, differ = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray = test::rayAtTriangle(rng, mesh, Vec3(-1.5f), Vec3(1.5f));
        Hit a, b;
        hits += intersectClosest(bvh, ray, a);
        intersectClosest(brute, ray, b);
        differ += a.t != b.t || a.primitive != b.primitive;
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(hits, 15000u);
}

TEST_P(Traversal, EmptySceneMisses) {
    Scene empty;
    const CompiledScene compiled = compileRenderScene(empty, test::layoutOptions(GetParam()));
    const RenderScene scene = compiled.view();
    Hit hit;
    EXPECT_FALSE(intersectClosest(scene, Ray{{0, 0, 0}, {0, 0, 1}, kInf}, hit));
    EXPECT_FALSE(hit.valid());
    EXPECT_FALSE(intersectAny(scene, Ray{{0, 0, 0}, {0, 0, 1}, kInf}));
    RenderScene none{};
    EXPECT_FALSE(intersectClosest(none, Ray{{0, 0, 0}, {0, 0, 1}, kInf}, hit));
}

TEST_P(Traversal, StatsCountWorkAndTheBvhPrunes) {
    Rng rng(6);
    const CompiledScene compiled =
        test::compileSingleMesh(test::makeSoup(SoupKind::Uniform, 20000, rng), GetParam());
    const RenderScene scene = compiled.view();
    RenderScene bf = scene;
    bf.bruteForce = 1;
    TraversalStats bvhStats, bfStats, anyStats;
    Hit hit;
    for (int i = 0; i < 1000; ++i) {
        const Ray ray = test::randomRay(rng, Vec3(-1.2f), Vec3(1.2f));
        intersectClosest(scene, ray, hit, &bvhStats);
        intersectClosest(bf, ray, hit, &bfStats);
        intersectAny(scene, ray, &anyStats);
    }
    EXPECT_GT(bvhStats.nodesVisited, 1000u);
    EXPECT_GT(bvhStats.primitivesTested, 0u);
    EXPECT_EQ(bfStats.primitivesTested, 1000u * 20000u);
    EXPECT_LT(bvhStats.primitivesTested * 100, bfStats.primitivesTested) << "the BVH should prune >99%";
    EXPECT_LE(anyStats.primitivesTested, bvhStats.primitivesTested) << "any-hit stops early";
}

}  // namespace
}  // namespace pt
