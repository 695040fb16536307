// LargeArray (render/util/large_array.h): scratch arrays of a build, on huge pages when large.
#include "render/util/large_array.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

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

// The huge pages under the mappings that overlap [address, address + bytes), from
// /proc/self/smaps (madvise splits a mapping where its advice starts, at a 2 MiB boundary).
long anonHugeBytesUnder(const void* address, size_t bytes) {
    std::ifstream smaps("/proc/self/smaps");
    const uintptr_t first = reinterpret_cast<uintptr_t>(address), last = first + bytes;
    bool overlaps = false;
    long total = 0;
    for (std::string line; std::getline(smaps, line);) {
        unsigned long begin = 0, end = 0;
        if (std::sscanf(line.c_str(), "%lx-%lx ", &begin, &end) == 2 && line.find(':') > line.find('-')) {
            overlaps = begin < last && first < end;
            continue;
        }
        long kib = 0;
        if (overlaps && std::sscanf(line.c_str(), "AnonHugePages: %ld kB", &kib) == 1) total += kib * 1024;
    }
    return total;
}

// A vector reserved on huge pages and then filled (a load's file bytes, its accessors' values,
// the compiled scene's arrays) sits on huge pages where the kernel offers them on request. A
// reservation advised after the fill, or over the wrong range, would leave it on 4 KiB pages.
TEST(ReserveOnHugePages, AReservedVectorIsFilledOnHugePages) {
    std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string modes;
    std::getline(mode, modes);
    if (modes.find("[madvise]") == std::string::npos)
        GTEST_SKIP() << "transparent huge pages are not offered on request here: '" << modes << "'";
    const size_t count = (size_t(16) << 20) / sizeof(uint32_t);
    std::vector<uint32_t> v;
    reserveOnHugePages(v, count);
    v.resize(count);
    for (size_t i = 0; i < count; ++i) v[i] = uint32_t(i);
    const long huge = anonHugeBytesUnder(v.data(), count * sizeof(uint32_t));
    // 16 MiB not aligned to 2 MiB holds at least 7 whole huge pages; one suffices to show the
    // advice took (memory short of free 2 MiB blocks may give fewer).
    EXPECT_GE(huge, long(kHugePageBytes));
    EXPECT_EQ(v[count - 1], uint32_t(count - 1));
}

}  // namespace
}  // namespace pt
