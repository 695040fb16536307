// The CPU's 8-ray packets (render/bvh/packet_traversal.h): each ray of a packet gets exactly the
// hit intersectClosest gives it alone (t, u, v, primitive and instance bit for bit), and the
// answer intersectAny gives it (also for segments that end at their closest hit or just past it),
// on soups that stress the walk differently, for coherent packets (a camera's neighbouring
// pixels), incoherent ones, packets of fewer than eight rays, finite segments and rays along axes;
// through an instance's transform and through the merged world-space BLAS; and where the walk does
// not apply, the rays are traced one by one.
#include "render/bvh/packet_traversal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/bvh/bvh_test_util.h"
#include "render/math/float_error.h"

namespace pt {
namespace {

using test::Rng;

// Eight rays from one point through a small patch of directions, as a camera's neighbouring
// pixels are: they enter the same nodes, and the walk goes down together.
std::vector<Ray> coherentPacket(Rng& rng, Vec3 lo, Vec3 hi) {
    const Vec3 origin = rng.inBox(lo, hi), target = rng.inBox(lo * 0.5f, hi * 0.5f);
    const float spread = rng.uniform(0.0f, 0.05f);
    std::vector<Ray> rays;
    for (uint32_t k = 0; k < kRayPacketSize; ++k) {
        const Vec3 offset(float(k % 4) * spread, float(k / 4) * spread, 0.0f);
        rays.push_back({origin, target + offset - origin, kInf});
    }
    return rays;
}

// Eight rays of every kind: hits behind others, misses, finite segments, zero components.
std::vector<Ray> mixedPacket(Rng& rng, const Mesh& mesh, Vec3 lo, Vec3 hi) {
    std::vector<Ray> rays;
    for (uint32_t k = 0; k < kRayPacketSize; ++k) {
        Ray ray = k % 2 ? test::randomRay(rng, lo, hi) : test::rayAtTriangle(rng, mesh, lo, hi);
        if (rng.uniform() < 0.2f) ray.tMax = rng.uniform(0.0f, 1.5f);
        if (rng.uniform() < 0.2f) {
            const int kept = int(rng.index(3));
            for (int a = 0; a < 3; ++a) {
                if (a != kept && rng.uniform() < 0.6f) ray.direction[a] = rng.uniform() < 0.5f ? 0.0f : -0.0f;
            }
        }
        rays.push_back(ray);
    }
    return rays;
}

// Appends `from`'s triangles to `to`, each corner moved by `place` (a Vec3 -> Vec3 function).
template <class Place>
void appendTriangles(Mesh& to, const Mesh& from, Place&& place) {
    const uint32_t base = uint32_t(to.positions.size());
    for (const Vec3& p : from.positions) to.positions.push_back(place(p));
    for (const uint32_t i : from.indices) to.indices.push_back(base + i);
}

// The instances' triangles in world space, one mesh.
Mesh worldMesh(const Mesh& mesh, const std::vector<test::InstanceSpec>& instances) {
    Mesh world;
    for (const test::InstanceSpec& instance : instances) {
        appendTriangles(world, mesh, [&](Vec3 p) { return instance.objectToWorld.transformPoint(p); });
    }
    return world;
}

bool sameHit(const Hit& a, const Hit& b) {
    return a.t == b.t && a.u == b.u && a.v == b.v && a.primitive == b.primitive && a.instance == b.instance;
}

// Traces `rays` (the first `count`) as a packet and one by one, for closest hits and for any
// hits (shadow rays: the finite segments among them end before some hits); returns the rays
// that differ in either and adds the valid hits to `hits`.
uint32_t packetDifferences(const RenderScene& scene, const std::vector<Ray>& rays, uint32_t count,
                           uint32_t& hits) {
    Hit packet[kRayPacketSize], single[kRayPacketSize];
    std::fill(packet, packet + kRayPacketSize, Hit{-1.0f, -1.0f, -1.0f, 7u, 7u});  // all overwritten
    intersectClosestPacket(scene, rays.data(), count, packet);
    const uint32_t occluded = intersectAnyPacket(scene, rays.data(), count);
    uint32_t differ = 0;
    for (uint32_t i = 0; i < count; ++i) {
        intersectClosest(scene, rays[i], single[i]);
        differ += !sameHit(packet[i], single[i]) ||
                  ((occluded >> i) & 1u) != uint32_t(intersectAny(scene, rays[i]));
        hits += single[i].valid();
    }
    // Shadow rays that end at their closest hit (t < tMax: only another surface at that t or
    // nearer occludes them) and one float past it (occluded).
    std::vector<Ray> atHit(rays.begin(), rays.begin() + count), pastHit = atHit;
    for (uint32_t i = 0; i < count; ++i) {
        if (!single[i].valid()) continue;
        atHit[i].tMax = single[i].t;
        pastHit[i].tMax = nextFloatUp(single[i].t);
    }
    for (const std::vector<Ray>* segments : {&atHit, &pastHit}) {
        const uint32_t segmentsOccluded = intersectAnyPacket(scene, segments->data(), count);
        for (uint32_t i = 0; i < count; ++i) {
            const bool anyHit = intersectAny(scene, (*segments)[i]);
            differ += ((segmentsOccluded >> i) & 1u) != uint32_t(anyHit);
            // One float past its closest hit, a segment holds that hit.
            differ += segments == &pastHit && single[i].valid() && !anyHit;
        }
        differ += segmentsOccluded >> count != 0;
    }
    differ += occluded >> count != 0;  // no lane past the packet's rays
    return differ;
}

// What packetDifferences finds over `packets` packets, coherent and mixed by turns, from the
// cube [-extent, extent]^3; the mixed ones aim at `targets`' triangles. Every fifth packet holds
// fewer than eight rays where `partial`.
struct PacketCheck {
    uint32_t differ = 0, hits = 0;
};
PacketCheck checkPackets(const RenderScene& scene, const Mesh& targets, Rng& rng, int packets, float extent,
                         bool partial = false) {
    PacketCheck check;
    const Vec3 lo(-extent), hi(extent);
    for (int p = 0; p < packets; ++p) {
        std::vector<Ray> rays = p % 2 ? coherentPacket(rng, lo, hi) : mixedPacket(rng, targets, lo, hi);
        if (p % 6 == 1) {
            // A camera along an axis: every direction's z exactly zero (of one sign), so the
            // interval test measures from padded origins (bvh_walk.h).
            for (Ray& ray : rays) ray.direction.z = p % 12 == 1 ? 0.0f : -0.0f;
        }
        const uint32_t count = partial && p % 5 == 0 ? 1 + rng.index(kRayPacketSize) : kRayPacketSize;
        check.differ += packetDifferences(scene, rays, count, check.hits);
    }
    return check;
}

TEST(PacketTraversal, EveryRayOfAPacketGetsItsOwnClosestHit) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Rng rng(31);
    for (const test::SoupKind kind :
         {test::SoupKind::Uniform, test::SoupKind::Clustered, test::SoupKind::Needles}) {
        SCOPED_TRACE(test::soupName(kind));
        const Mesh mesh = test::makeSoup(kind, 20000, rng);
        const CompiledScene compiled = test::compileSingleMesh(mesh, test::Layout::Wide);
        const RenderScene scene = compiled.view();
        ASSERT_TRUE(packetWalkApplies(scene));
        const PacketCheck check = checkPackets(scene, mesh, rng, 3000, 1.2f, true);
        EXPECT_EQ(check.differ, 0u);
        EXPECT_GT(check.hits, 4000u) << "the rays should hit often enough to test something";
    }
}

// Coincident triangles: ties in t go to the lower primitive whichever leaf a lane meets first,
// and lanes that leave the packet to finish a subtree alone keep the hit they already have (it
// decides their ties there). Each of a few hundred triangles is repeated 24 times, so its copies
// fill several leaves in different subtrees, the copies' indices interleaved with the others'.
TEST(PacketTraversal, TiesGoToTheLowerPrimitiveAsOneRayAtATime) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Rng rng(32);
    Mesh mesh = test::makeSoup(test::SoupKind::Uniform, 300, rng);
    const size_t original = mesh.indices.size();
    for (int copy = 1; copy < 24; ++copy) {
        for (size_t i = 0; i < original; ++i) mesh.indices.push_back(mesh.indices[i]);
    }
    const CompiledScene compiled = test::compileSingleMesh(mesh, test::Layout::Wide);
    ASSERT_TRUE(packetWalkApplies(compiled.view()));
    const PacketCheck check = checkPackets(compiled.view(), mesh, rng, 4000, 1.2f);
    EXPECT_EQ(check.differ, 0u);
    EXPECT_GT(check.hits, 4000u);
}

// One instance with a transform (object-space rays) and instances all merged into the world-space
// BLAS (hits reported as the instance triangles they copy).
TEST(PacketTraversal, InstancesThroughTheirTransformAndTheMergedBlas) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Rng rng(33);
    const Mesh mesh = test::makeSoup(test::SoupKind::Clustered, 4000, rng);
    const float half = 0.35f;  // a turn of 0.7 radians about (0, 1, 1) / sqrt(2)
    const Vec4 turn(0.0f, std::sin(half) * 0.70710678f, std::sin(half) * 0.70710678f, std::cos(half));
    const Affine3 turned =
        translationTransform(Vec3(0.3f, -0.2f, 0.1f)) * rotationTransform(turn) * scaleTransform(Vec3(0.8f));
    CompileOptions wide = test::layoutOptions(test::Layout::Wide);
    const CompiledScene one = test::compileTestScene({mesh}, {{0, turned}}, wide);
    std::vector<test::InstanceSpec> specs;
    for (int i = 0; i < 4; ++i) {
        specs.push_back(
            {0, translationTransform(Vec3(float(i) * 0.7f - 1.0f, 0.0f, 0.0f)) * scaleTransform(Vec3(0.4f))});
    }
    const CompiledScene merged = test::compileTestScene({mesh}, specs, wide);
    ASSERT_TRUE(merged.merged.active());
    ASSERT_EQ(merged.tlasInstanceIndices.size(), 1u)
        << "every instance merged: the TLAS holds the merged BLAS";
    for (const CompiledScene* compiled : {&one, &merged}) {
        const std::vector<test::InstanceSpec> placed =
            compiled == &one ? std::vector<test::InstanceSpec>{{0, turned}} : specs;
        const Mesh world = worldMesh(mesh, placed);  // the rays aim at the instances' triangles
        const RenderScene scene = compiled->view();
        ASSERT_TRUE(packetWalkApplies(scene));
        const PacketCheck check = checkPackets(scene, world, rng, 2000, 1.5f);
        EXPECT_EQ(check.differ, 0u);
        EXPECT_GT(check.hits, 2000u);
    }
}

// Instances under a TLAS, each with its own BLAS (merging off), among them a BLAS of spheres
// (tested lane by lane), and two instances that share triangles at one place: the clustered
// soup, and a mesh of the same triangles plus others beyond them, whose box differs, so the
// TLAS holds them apart. Every hit on a shared triangle ties in t between the two; the
// single-ray walk gives it to the lower instance, and so must the packet, whatever order it
// meets them in.
TEST(PacketTraversal, InstancesUnderATlasIncludingTwoThatTieEverywhere) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Rng rng(35);
    const Mesh shared = test::makeSoup(test::SoupKind::Clustered, 3000, rng);
    Mesh wider = shared;  // the same triangles, and as many again shifted along x
    appendTriangles(wider, shared, [](Vec3 p) { return p + Vec3(1.2f, 0.3f, 0.0f); });
    std::vector<Vec4> spheres;
    for (int i = 0; i < 200; ++i) {
        const Vec3 c = rng.inBox(Vec3(-1.0f), Vec3(1.0f));
        spheres.push_back(Vec4(c.x, c.y, c.z, rng.uniform(0.01f, 0.08f)));
    }
    const std::vector<Mesh> meshes = {shared, wider, test::makeSoup(test::SoupKind::Uniform, 2000, rng),
                                      test::makeSphereMesh(spheres)};
    const std::vector<test::InstanceSpec> specs = {
        {0, Affine3{}},
        {2, translationTransform(Vec3(-0.5f, 0.3f, 0.2f)) * scaleTransform(Vec3(0.5f))},
        {1, Affine3{}},  // shares instance 0's triangles
        {3, scaleTransform(Vec3(0.9f))},
        {2, translationTransform(Vec3(0.6f, -0.6f, 0.0f)) * scaleTransform(Vec3(0.3f))},
    };
    CompileOptions options = test::layoutOptions(test::Layout::Wide);
    options.mergeSmallInstances = false;
    const CompiledScene compiled = test::compileTestScene(meshes, specs, options);
    const RenderScene scene = compiled.view();
    ASSERT_TRUE(packetWalkApplies(scene));
    ASSERT_GT(compiled.tlasInstanceIndices.size(), 1u);
    const PacketCheck check = checkPackets(scene, shared, rng, 4000, 1.3f, true);
    EXPECT_EQ(check.differ, 0u);
    EXPECT_GT(check.hits, 6000u);
    // The ties are there: rays at the shared triangles hit them, on instance 0, never on 2
    // (whose first triangles they are).
    const uint32_t sharedCount = uint32_t(shared.indices.size() / 3);
    uint32_t onZero = 0, sharedOnTwo = 0;
    for (int i = 0; i < 4000; ++i) {
        Hit hit;
        intersectClosest(scene, test::rayAtTriangle(rng, shared, Vec3(-1.3f), Vec3(1.3f)), hit);
        onZero += hit.valid() && hit.instance == 0;
        sharedOnTwo += hit.valid() && hit.instance == 2 && hit.primitive < sharedCount;
    }
    EXPECT_GT(onZero, 1000u);
    EXPECT_EQ(sharedOnTwo, 0u);
}

// Many instances (48 of a soup on a 4 x 4 x 3 grid, each scaled and turned its own way): the
// packets walk the binary TLAS, a deep one here, where one ray at a time walks its 8-wide form
// (interior nodes too), and every ray's hit is the same. (An 8-wide TLAS walked by the packets
// tests a box eight rays at a time for each of a node's eight children where the binary one
// tests two: camera rays on the shared Balloon ran 0.63-0.95x as fast with it in six
// alternated one-thread runs, and a field of 64 instances anywhere from 0.69 to 1.43x.)
TEST(PacketTraversal, ManyInstancesUnderAWideTlasOfSeveralLevels) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Rng rng(37);
    const Mesh soup = test::makeSoup(test::SoupKind::Clustered, 400, rng);
    std::vector<test::InstanceSpec> specs;
    for (int x = 0; x < 4; ++x) {
        for (int y = 0; y < 4; ++y) {
            for (int z = 0; z < 3; ++z) {
                const Vec3 at(-1.5f + float(x), -1.5f + float(y), -1.0f + float(z));
                const float turn = rng.uniform(0.0f, kPi);
                specs.push_back({0, translationTransform(at) *
                                        rotationTransform({0.0f, std::sin(turn), 0.0f, std::cos(turn)}) *
                                        scaleTransform(Vec3(rng.uniform(0.3f, 0.5f)))});
            }
        }
    }
    CompileOptions options = test::layoutOptions(test::Layout::Wide);
    options.mergeSmallInstances = false;
    const CompiledScene compiled = test::compileTestScene({soup}, specs, options);
    const RenderScene scene = compiled.view();
    ASSERT_TRUE(packetWalkApplies(scene));
    ASSERT_GT(compiled.tlasWideNodes.size(), 1u) << "a wide TLAS of more than its root";
    ASSERT_GT(compiled.tlasNodes.size(), 64u);
    // The mixed packets aim at the soup's triangles in every instance.
    const PacketCheck check = checkPackets(scene, worldMesh(soup, specs), rng, 3000, 2.2f, true);
    EXPECT_EQ(check.differ, 0u);
    EXPECT_GT(check.hits, 4000u);
}

// The merged BLAS beside instances of their own under one TLAS: small instances merge (the
// soup's copies), the large one keeps its BLAS, and the soup's copies coincide with triangles
// of that large mesh, so hits tie between the merged BLAS and the instance.
TEST(PacketTraversal, TheMergedBlasBesideInstancesUnderATlas) {
    if (supportedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "this processor runs no AVX2";
    Rng rng(36);
    const Mesh small = test::makeSoup(test::SoupKind::Clustered, 500, rng);
    Mesh large = test::makeSoup(test::SoupKind::Uniform, 70000, rng);  // too large to merge
    appendTriangles(large, small, [](Vec3 p) { return p; });
    const std::vector<test::InstanceSpec> specs = {
        {0, Affine3{}},  // its triangles are also the large mesh's
        {0, translationTransform(Vec3(0.5f, 0.2f, 0.0f)) * scaleTransform(Vec3(0.5f))},
        {1, Affine3{}},
    };
    const CompiledScene compiled =
        test::compileTestScene({small, large}, specs, test::layoutOptions(test::Layout::Wide));
    ASSERT_TRUE(compiled.merged.active());
    ASSERT_GT(compiled.tlasInstanceIndices.size(), 1u) << "the merged BLAS and the large instance";
    const RenderScene scene = compiled.view();
    ASSERT_TRUE(packetWalkApplies(scene));
    const PacketCheck check = checkPackets(scene, small, rng, 3000, 1.3f, true);
    EXPECT_EQ(check.differ, 0u);
    EXPECT_GT(check.hits, 6000u);
}

// Where the walk does not apply (SSE2, the binary layout, brute force) the packet's rays are
// traced one by one, with the same hits.
TEST(PacketTraversal, ScenesTheWalkDoesNotTakeAreTracedRayByRay) {
    Rng rng(34);
    const Mesh mesh = test::makeSoup(test::SoupKind::Uniform, 2000, rng);
    const CompiledScene binary = test::compileSingleMesh(mesh, test::Layout::Binary);
    EXPECT_FALSE(packetWalkApplies(binary.view()));
    RenderScene bruteForce = binary.view();
    bruteForce.bruteForce = 1;
    EXPECT_FALSE(packetWalkApplies(bruteForce));
    const CompiledScene wide = test::compileSingleMesh(mesh, test::Layout::Wide);
    const ScopedSimdLevel sse2(SimdLevel::Sse2);
    EXPECT_FALSE(packetWalkApplies(wide.view()));
    for (const RenderScene& scene : {binary.view(), bruteForce, wide.view()}) {
        const PacketCheck check = checkPackets(scene, mesh, rng, 200, 1.2f, true);
        EXPECT_EQ(check.differ, 0u);
        EXPECT_GT(check.hits, 200u);
    }
}

}  // namespace
}  // namespace pt
