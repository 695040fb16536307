// LargeArray (render/util/large_array.h): scratch arrays of a build, on huge pages when large.
#include "render/util/large_array.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

namespace pt {
namespace {

TEST(LargeArray, ALargeArrayStartsOnAHugePageAndHoldsEveryElement) {
    const size_t count = (size_t(5) << 20) / sizeof(uint32_t) + 3;  // 5 MiB and a bit: not whole pages
    const LargeArray<uint32_t> a(count);
    ASSERT_EQ(a.size(), count);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(a.data()) % kHugePageBytes, 0u);
    for (size_t i = 0; i < count; ++i) a[i] = uint32_t(i * 2654435761u);
    size_t wrong = 0;
    for (size_t i = 0; i < count; ++i) wrong += a[i] != uint32_t(i * 2654435761u);
    EXPECT_EQ(wrong, 0u);
}

TEST(LargeArray, SmallAndEmptyArrays) {
    const LargeArray<double> small(7);
    ASSERT_EQ(small.size(), 7u);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(small.data()) % alignof(double), 0u);
    for (size_t i = 0; i < 7; ++i) small[i] = double(i);
    EXPECT_EQ(small[6], 6.0);
    const LargeArray<double> empty(0);
    EXPECT_EQ(empty.size(), 0u);
    EXPECT_EQ(empty.data(), nullptr);
    const LargeArray<double> none;
    EXPECT_EQ(none.data(), nullptr);
}

// Moved, the array's elements go with it and the source is left empty (a deferred mesh's boxes
// move from the scene compiler to the background build).
TEST(LargeArray, AMoveTakesTheElementsAndEmptiesTheSource) {
    LargeArray<int> a(3);
    a[0] = 7, a[1] = 8, a[2] = 9;
    const int* elements = a.data();
    LargeArray<int> b(std::move(a));
    EXPECT_EQ(b.data(), elements);
    EXPECT_EQ(b.size(), 3u);
    EXPECT_EQ(b[2], 9);
    EXPECT_TRUE(a.empty());  // NOLINT(bugprone-use-after-move): what a move leaves is the point
    EXPECT_EQ(a.data(), nullptr);
    LargeArray<int> c;
    c = std::move(b);
    EXPECT_EQ(c.size(), 3u);
    EXPECT_EQ(c[0], 7);
    EXPECT_TRUE(b.empty());
}

}  // namespace
}  // namespace pt
