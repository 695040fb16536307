// AovSet (render/backend/aov.h), the bookkeeping of which samples each AOV holds: an AOV added
// later starts at its sample, a capped one records until it holds the cap and then skips, the
// samples until the first capped AOV fills, and changes of the AOVs keep or drop what each held.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>

#include "render/backend/aov.h"

namespace pt {
namespace {

TEST(AovSet, ACappedAovRecordsUntilItHoldsTheCapThenSkips) {
    AovSet set{aovBit(Aov::Albedo) | aovBit(Aov::Depth) | aovBit(Aov::Variance), {}, {}};
    const AovSampleCap cap{aovBit(Aov::Albedo), 5};
    EXPECT_EQ(set.recording(cap, 0), set.mask);
    EXPECT_EQ(set.samplesUntilFull(cap, 0), 5u);
    set.skip(set.recording(cap, 0), 3);
    EXPECT_EQ(set.samplesUntilFull(cap, 3), 2u);
    set.skip(set.recording(cap, 3), 2);
    EXPECT_EQ(set.samples(Aov::Albedo, 5), 5u);
    EXPECT_EQ(set.recording(cap, 5), aovBit(Aov::Depth) | aovBit(Aov::Variance)) << "full";
    EXPECT_EQ(set.samplesUntilFull(cap, 5), UINT32_MAX) << "no capped AOV still records";
    set.skip(set.recording(cap, 5), 10);
    EXPECT_EQ(set.samples(Aov::Albedo, 15), 5u);
    EXPECT_EQ(set.samples(Aov::Depth, 15), 15u);
    const AovSampleCounts counts = set.samplesAt(15);
    EXPECT_EQ(counts[Aov::Albedo], 5u);
    EXPECT_EQ(counts[Aov::Variance], 15u);
    EXPECT_EQ(counts[Aov::Uv], 0u) << "not accumulated";

    // Lifted, it records again; its skipped samples stay skipped.
    EXPECT_EQ(set.recording({}, 15), set.mask);
    set.skip(set.mask, 2);
    EXPECT_EQ(set.samples(Aov::Albedo, 17), 7u);
}

TEST(AovSet, ChangesKeepWhatTheKeptAovsHeldAndStartTheNewOnesAfresh) {
    AovSet set{aovBit(Aov::Albedo) | aovBit(Aov::Depth), {}, {}};
    set.skip(aovBit(Aov::Depth), 4);  // albedo capped from the start, say
    const AovSet changed = set.changedTo(aovBit(Aov::Albedo) | aovBit(Aov::Uv), 4);
    EXPECT_EQ(changed.samples(Aov::Albedo, 6), 2u) << "kept with its skips";
    EXPECT_EQ(changed.samples(Aov::Uv, 6), 2u) << "new from sample 4";
    const AovSet back = changed.changedTo(aovBit(Aov::Albedo) | aovBit(Aov::Depth), 6);
    EXPECT_EQ(back.samples(Aov::Depth, 9), 3u) << "dropped and added again: starts afresh";
}

TEST(AovSet, TwoCappedAovsStopEachAtItsOwnFill) {
    // One added later than the other: the first to fill ends the segment; the other goes on.
    AovSet set{aovBit(Aov::Albedo), {}, {}};
    set.skip(set.mask, 2);
    set = set.changedTo(aovBit(Aov::Albedo) | aovBit(Aov::Depth), 2);
    const AovSampleCap cap{aovBit(Aov::Albedo) | aovBit(Aov::Depth), 4};
    EXPECT_EQ(set.samplesUntilFull(cap, 2), 2u) << "albedo holds 2 of 4";
    set.skip(set.recording(cap, 2), 2);
    EXPECT_EQ(set.recording(cap, 4), aovBit(Aov::Depth));
    EXPECT_EQ(set.samplesUntilFull(cap, 4), 2u) << "depth holds 2 of 4";
}

TEST(AovSet, OnlyPathAovsCanBeCapped) {
    EXPECT_THROW(checkAovSampleCap({aovBit(Aov::Variance), 4}), std::invalid_argument);
    EXPECT_THROW(checkAovSampleCap({aovBit(Aov::SampleCount), 4}), std::invalid_argument);
    EXPECT_THROW(checkAovSampleCap({aovBit(Aov::Depth), 0}), std::invalid_argument);
    EXPECT_NO_THROW(checkAovSampleCap({kPathAovs, 1}));
    EXPECT_NO_THROW(checkAovSampleCap({}));
}

}  // namespace
}  // namespace pt
