// BackgroundBvhBuild: the binned SAH build on a thread of its own gives the builder's tree,
// finishes without being waited for, and is joined (never left running) when dropped.
#include "render/bvh/background_bvh_build.h"

#include <gtest/gtest.h>

#include <algorithm>
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
    const Bvh background = build.take();
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

TEST(BackgroundBvhBuild, FinishesWithoutBeingTakenAndIsWaitedForOnDestruction) {
    test::Rng rng(16);
    const std::vector<Aabb> bounds =
        test::triangleBounds(test::makeSoup(test::SoupKind::Uniform, 50000, rng));
    {
        BackgroundBvhBuild finished(copyOf(bounds));
        while (!finished.ready()) std::this_thread::yield();  // done without anyone taking it
        EXPECT_EQ(finished.take().primIndices.size(), bounds.size());
    }
    { BackgroundBvhBuild dropped(copyOf(bounds)); }  // joined, or std::thread's destructor terminates
}

}  // namespace
}  // namespace pt
