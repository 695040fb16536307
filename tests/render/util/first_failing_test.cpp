// firstFailing (render/util/first_failing.h): a parallel scan that finds what a serial one would.
#include "render/util/first_failing.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace pt {
namespace {

TEST(FirstFailing, FindsTheLowestFailingIndexWhateverChunkSeesOneFirst) {
    const size_t count = 5'000'000;  // many chunks, run on every thread
    for (const std::vector<size_t>& failing :
         {std::vector<size_t>{4'999'999}, {3'000'000, 70'000, 4'000'001}, {0, 2'500'000}, {65'535, 65'536}}) {
        std::vector<char> fails(count, 0);
        for (size_t i : failing) fails[i] = 1;
        size_t lowest = count;
        for (size_t i : failing) lowest = std::min(lowest, i);
        EXPECT_EQ(firstFailing(count, [&](size_t i) { return fails[i] != 0; }), lowest);
    }
}

TEST(FirstFailing, NoneFailingGivesTheCountAndChecksEveryIndex) {
    const size_t count = 1'000'003;
    std::atomic<size_t> checked{0};
    EXPECT_EQ(firstFailing(count,
                           [&](size_t) {
                               checked.fetch_add(1, std::memory_order_relaxed);
                               return false;
                           }),
              count);
    EXPECT_EQ(checked.load(), count);
    EXPECT_EQ(firstFailing(0, [](size_t) { return true; }), 0u);
}

}  // namespace
}  // namespace pt
