// The CPU's 8-wide BVH (render/bvh/wide_bvh.h): the collapse keeps every leaf of the binary
// tree once with its box, the wide walk visits fewer nodes than the binary one for the same
// hits, and a host refit reaches the wide boxes. (Its hits against brute force are the
// Layouts/ suites of traversal_test.cpp, two_level_traversal_test.cpp and watertight_test.cpp.)
#include "render/bvh/wide_bvh.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "render/backend/cpu/cpu_backend.h"
#include "render/bvh/binned_sah_builder.h"
#include "render/bvh/bvh_test_util.h"
#include "render/compile/wide_blases.h"
#include "support/scene_builder.h"

namespace pt {
namespace {

using test::Rng;

// Every binary leaf, by its primitive range, and the box it has.
std::map<std::pair<uint32_t, uint32_t>, const BvhNode*> binaryLeaves(const Bvh& bvh) {
    std::map<std::pair<uint32_t, uint32_t>, const BvhNode*> leaves;
    for (const BvhNode& n : bvh.nodes) {
        if (n.isLeaf()) leaves[{n.leftOrFirst, n.count}] = &n;
    }
    return leaves;
}

TEST(WideBvh, TheCollapseKeepsEveryLeafOnceWithItsBox) {
    Rng rng(3);
    for (const uint32_t triangles : {1u, 2u, 3u, 5u, 17u, 1000u, 20000u}) {
        SCOPED_TRACE(std::to_string(triangles) + " triangles");
        const std::vector<Aabb> boxes =
            test::triangleBounds(test::makeSoup(test::SoupKind::Clustered, triangles, rng));
        const Bvh bvh = buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()));
        const WideBvh wide = collapseToWide(bvh.nodes.data(), uint32_t(bvh.nodes.size()));
        std::map<std::pair<uint32_t, uint32_t>, const BvhNode*> leaves = binaryLeaves(bvh);
        const size_t leafCount = leaves.size();
        uint32_t interiorSlots = 0;
        for (size_t n = 0; n < wide.nodes.size(); ++n) {
            const WideBvhNode& node = wide.nodes[n];
            for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
                const uint32_t source = wide.sourceNodes[n * WideBvhNode::kWidth + s];
                if (node.count[s] == WideBvhNode::kEmpty) {
                    EXPECT_EQ(source, WideBvhNode::kEmpty);
                    continue;
                }
                const BvhNode& from = bvh.nodes.at(source);
                EXPECT_EQ(node.loX[s], from.lo.x);
                EXPECT_EQ(node.hiZ[s], from.hi.z);
                if (node.count[s] == 0) {
                    ++interiorSlots;
                    EXPECT_LT(node.child[s], wide.nodes.size());
                    continue;
                }
                EXPECT_EQ(leaves.erase({node.child[s], node.count[s]}), 1u) << "a leaf missing or repeated";
            }
        }
        EXPECT_TRUE(leaves.empty()) << leaves.size() << " binary leaves are not in the wide tree";
        EXPECT_EQ(interiorSlots + 1, wide.nodes.size()) << "every wide node but the root hangs from one slot";
        if (leafCount >= 4) {
            // Eight children a node, mostly (measured: one wide node per six binary ones).
            EXPECT_LE(wide.nodes.size(), (bvh.nodes.size() + 4) / 5);
        }
    }
}

// With leaves of up to four primitives (triangle BLASes, tested a block at a time): every
// primitive in exactly one wide leaf of at most four, each leaf's box its source node's, and
// fewer nodes than with the binary leaves.
TEST(WideBvh, MergedLeavesCoverEveryPrimitiveOnceWithTheirSubtreesBoxes) {
    Rng rng(4);
    for (const uint32_t triangles : {1u, 2u, 3u, 4u, 5u, 17u, 1000u, 20000u}) {
        SCOPED_TRACE(std::to_string(triangles) + " triangles");
        const std::vector<Aabb> boxes =
            test::triangleBounds(test::makeSoup(test::SoupKind::Uniform, triangles, rng));
        const Bvh bvh = buildBinnedSahBvh(boxes.data(), uint32_t(boxes.size()));
        const WideBvh merged = collapseToWide(bvh.nodes.data(), uint32_t(bvh.nodes.size()), 4);
        const WideBvh plain = collapseToWide(bvh.nodes.data(), uint32_t(bvh.nodes.size()));
        std::vector<int> covered(triangles, 0);
        uint32_t interiorSlots = 0;
        for (size_t n = 0; n < merged.nodes.size(); ++n) {
            const WideBvhNode& node = merged.nodes[n];
            for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s) {
                if (node.count[s] == WideBvhNode::kEmpty) continue;
                ASSERT_LT(merged.sourceNodes[n * WideBvhNode::kWidth + s], bvh.nodes.size());
                if (node.count[s] == 0) {
                    ++interiorSlots;
                    continue;
                }
                EXPECT_LE(node.count[s], 4u);
                Aabb box;
                for (uint32_t i = node.child[s]; i < node.child[s] + node.count[s]; ++i) {
                    ++covered.at(bvh.primIndices.at(i));
                    box.grow(boxes[bvh.primIndices[i]]);
                }
                const float slot[6] = {node.loX[s], node.loY[s], node.loZ[s],
                                       node.hiX[s], node.hiY[s], node.hiZ[s]};
                const float expected[6] = {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z};
                for (int k = 0; k < 6; ++k)
                    EXPECT_EQ(slot[k], expected[k]) << "the slot's box is its primitives' union";
            }
        }
        for (uint32_t t = 0; t < triangles; ++t) EXPECT_EQ(covered[t], 1) << "triangle " << t;
        EXPECT_EQ(interiorSlots + 1, merged.nodes.size());
        EXPECT_LE(merged.nodes.size(), plain.nodes.size());
        if (triangles >= 1000) {
            EXPECT_LT(merged.nodes.size() * 3, plain.nodes.size() * 2) << "small subtrees merged";
        }
    }
}

TEST(WideBvh, AnEmptyTreeHasARootWithNoSlot) {
    const Bvh empty = buildBinnedSahBvh(nullptr, 0);
    for (const uint32_t leafPrimitives : {0u, 4u}) {
        const WideBvh wide = collapseToWide(empty.nodes.data(), uint32_t(empty.nodes.size()), leafPrimitives);
        ASSERT_EQ(wide.nodes.size(), 1u);
        for (uint32_t s = 0; s < WideBvhNode::kWidth; ++s)
            EXPECT_EQ(wide.nodes[0].count[s], WideBvhNode::kEmpty);
    }
}

// The same closest hits through fewer, wider nodes: the walk the CPU runs is the wide one.
TEST(WideBvh, TheWideWalkVisitsFewerNodesForTheSameHits) {
    const auto [binaryStats, wideStats] = test::walkWorkAgainstBinary(test::Layout::Wide);
    // Nodes popped (leaves included): eight children a node and merged leaves (measured: 2.7x
    // fewer).
    EXPECT_LT(wideStats.nodesVisited * 2, binaryStats.nodesVisited);
    // Subtrees of up to eight triangles are one leaf there, tested four at a time: more
    // triangles are tested (measured: 7.0x), but not eight for each the binary walk tests.
    EXPECT_LT(wideStats.primitivesTested, binaryStats.primitivesTested * 8);
    EXPECT_GT(wideStats.primitivesTested, binaryStats.primitivesTested * 0.9);
}

// A vertex edit refits the binary BLAS on the host; its wide boxes must follow, or rays would
// miss the moved triangles.
TEST(WideBvh, AHostRefitReachesTheWideBoxes) {
    Rng rng(12);
    Scene scene;
    scene.render = {16, 16, 1, 1, 0};
    scene.meshes.push_back(test::makeSoup(test::SoupKind::Uniform, 3000, rng));
    Instance instance;
    instance.materials = {test::addMaterial(scene, "grey", test::diffuse({0.5f, 0.5f, 0.5f}))};
    scene.instances.push_back(instance);
    CpuBackend edited;
    edited.sync(scene, SceneChanges::All, {});
    for (Vec3& p : scene.meshes[0].positions) p = p * 1.5f + Vec3(0.3f, 0.0f, 0.0f);
    EXPECT_EQ(edited.sync(scene, SceneChanges::Geometry, {}).action, "refit");
    CpuBackend fresh;
    fresh.sync(scene, SceneChanges::All, {});
    std::vector<Ray> rays;
    for (int i = 0; i < 20000; ++i)
        rays.push_back(test::rayAtTriangle(rng, scene.meshes[0], Vec3(-2.0f), Vec3(2.0f)));
    std::vector<Hit> a, b;
    edited.traceRays(rays, false, 1, &a);
    fresh.traceRays(rays, false, 1, &b);
    size_t differ = 0;
    for (size_t i = 0; i < rays.size(); ++i) differ += a[i].valid() != b[i].valid() || a[i].t != b[i].t;
    EXPECT_EQ(differ, 0u);
}

}  // namespace
}  // namespace pt
