// BackgroundBvhBuild: the binned SAH build on a thread of its own gives the builder's tree (and
// its compressed form where asked), finishes without being waited for, and is joined (never left running)
// when dropped.
#include "render/bvh/background_bvh_build.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <thread>

#include "render/bvh/bvh_test_util.h"

namespace pt {
namespace {

// The build's own copy of `bounds` (it takes a LargeArray, as the scene compiler fills one).
LargeArray<Aabb> copyOf(const std::vector<Aabb>& bounds) {
    LargeArray<Aabb> copy(bounds.size());
    std::copy(bounds.begin(), bounds.end(), copy.data());
    return copy;
}

// The thread's tree is the builder's, node for node.
TEST(BackgroundBvhBuild, BuildsTheBinnedSahTree) {
    test::Rng rng(15);
    const std::vector<Aabb> bounds =
        test::triangleBounds(test::makeSoup(test::SoupKind::Clustered, 20000, rng));
    const Bvh direct = buildBinnedSahBvh(bounds.data(), uint32_t(bounds.size()));
    BackgroundBvhBuild build(copyOf(bounds));
    const Bvh& background = build.tree();
    EXPECT_TRUE(build.ready());
    ASSERT_EQ(background.nodes.size(), direct.nodes.size());
    EXPECT_EQ(background.primIndices, direct.primIndices);
    for (size_t i = 0; i < direct.nodes.size(); ++i) {
        ASSERT_EQ(background.nodes[i].lo, direct.nodes[i].lo) << i;
        ASSERT_EQ(background.nodes[i].hi, direct.nodes[i].hi) << i;
        ASSERT_EQ(background.nodes[i].leftOrFirst, direct.nodes[i].leftOrFirst) << i;
        ASSERT_EQ(background.nodes[i].count, direct.nodes[i].count) << i;
    }
}

// Asked for, the compressed form is the collapse of the thread's tree, byte for byte; not asked
// for, it is empty.
TEST(BackgroundBvhBuild, CompressesItsTreeWhereAsked) {
    test::Rng rng(17);
    const std::vector<Aabb> bounds =
        test::triangleBounds(test::makeSoup(test::SoupKind::Clustered, 20000, rng));
    BackgroundBvhBuild build(copyOf(bounds), true);
    const Bvh& tree = build.tree();
    const CompressedWideBvh background = build.takeCompressed();
    const CompressedWideBvh direct =
        compressToWide(tree.nodes.data(), uint32_t(tree.nodes.size()), tree.primIndices.data());
    ASSERT_GT(direct.nodes.size(), 1u);
    ASSERT_EQ(background.nodes.size(), direct.nodes.size());
    EXPECT_EQ(0, std::memcmp(background.nodes.data(), direct.nodes.data(),
                             direct.nodes.size() * sizeof(CompressedWideNode)));
    EXPECT_EQ(background.primIndices, direct.primIndices);
    EXPECT_EQ(background.sourceNodes, direct.sourceNodes);

    BackgroundBvhBuild binaryOnly(copyOf(bounds));
    EXPECT_EQ(binaryOnly.tree().nodes.size(), tree.nodes.size());
    EXPECT_TRUE(binaryOnly.takeCompressed().nodes.empty());
}

TEST(BackgroundBvhBuild, FinishesWithoutBeingTakenAndIsWaitedForOnDestruction) {
    test::Rng rng(16);
    const std::vector<Aabb> bounds =
        test::triangleBounds(test::makeSoup(test::SoupKind::Uniform, 50000, rng));
    {
        BackgroundBvhBuild finished(copyOf(bounds));
        while (!finished.finished()) std::this_thread::yield();  // done without anyone taking it
        EXPECT_TRUE(finished.ready());
        EXPECT_EQ(finished.tree().primIndices.size(), bounds.size());
    }
    { BackgroundBvhBuild dropped(copyOf(bounds)); }  // joined, or std::thread's destructor terminates
}

}  // namespace
}  // namespace pt
