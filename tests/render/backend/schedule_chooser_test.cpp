#include "render/backend/schedule_chooser.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

// Runs a trial where a megakernel pass takes `megakernel` seconds and a wavefront pass
// `wavefront` (the first pass of each twice as long: its warm-up), and returns the passes run.
int runTrial(ScheduleChooser& c, double megakernel, double wavefront) {
    int passes = 0, megakernelRuns = 0, wavefrontRuns = 0;
    while (!c.decided()) {
        const PassSchedule next = c.next();
        const bool m = next.megakernel;
        int& runs = m ? megakernelRuns : wavefrontRuns;
        c.record(next, (m ? megakernel : wavefront) * (runs == 0 ? 2.0 : 1.0));
        ++runs;
        ++passes;
        if (passes > 100) break;
    }
    return passes;
}

TEST(ScheduleChooser, AlternatesDuringTheTrialThenRunsTheFaster) {
    ScheduleChooser c;
    c.setKey(1);
    EXPECT_EQ(c.choice(), "measuring");
    // Megakernel passes take 10 ms, wavefront passes 4 ms.
    for (uint32_t pass = 0; pass < 2 * ScheduleChooser::kTrialPassesEach; ++pass) {
        EXPECT_FALSE(c.decided()) << "pass " << pass;
        const PassSchedule next = c.next();
        EXPECT_EQ(next.megakernel, pass % 2 == 0) << "the schedules take turns, pass " << pass;
        EXPECT_FALSE(next.compressedWalk) << "no compressed nodes to try, pass " << pass;
        c.record(next, next.megakernel ? 0.010 : 0.004);
    }
    EXPECT_TRUE(c.decided());
    EXPECT_FALSE(c.next().megakernel);
    EXPECT_EQ(c.walkChoice(), "");
    EXPECT_EQ(c.choice(), "wavefront");
    EXPECT_DOUBLE_EQ(c.wavefrontRate(), 250.0);
    EXPECT_DOUBLE_EQ(c.megakernelRate(), 100.0);
}

TEST(ScheduleChooser, TheFirstPassesWarmUpDoNotDecide) {
    // The megakernel is faster once warm, though its first pass is slower than the wavefront's.
    ScheduleChooser c;
    c.setKey(7);
    runTrial(c, 0.003, 0.005);
    EXPECT_TRUE(c.next().megakernel);
    EXPECT_EQ(c.choice(), "megakernel");
}

TEST(ScheduleChooser, ANewKeyStartsANewTrialAndTheSameKeyKeepsTheDecision) {
    ScheduleChooser c;
    c.setKey(1);
    runTrial(c, 0.003, 0.005);
    c.setKey(1);
    EXPECT_TRUE(c.decided());
    c.setKey(2);
    EXPECT_FALSE(c.decided());
    EXPECT_EQ(c.megakernelRate(), 0.0);
    runTrial(c, 0.009, 0.005);
    EXPECT_EQ(c.choice(), "wavefront");
}

// The editor alternates keys (one-sample waves after each edit, longer ones after): a key that
// comes back has its decision, and its rates, without a new trial.
TEST(ScheduleChooser, AKeyThatComesBackKeepsItsDecision) {
    ScheduleChooser c;
    c.setKey(10);
    runTrial(c, 0.003, 0.005);  // one sample a wave: the megakernel
    c.setKey(11);
    EXPECT_FALSE(c.decided());
    runTrial(c, 0.004, 0.002);  // longer waves: the wavefront
    c.setKey(10);
    EXPECT_TRUE(c.decided());
    EXPECT_EQ(c.choice(), "megakernel");
    EXPECT_DOUBLE_EQ(c.megakernelRate(), 1.0 / 0.003);
    c.setKey(11);
    EXPECT_EQ(c.choice(), "wavefront");
    EXPECT_EQ(runTrial(c, 0.004, 0.002), 0);  // nothing left to measure
}

// With compressed nodes the trial runs each schedule with each walk, in turn, and the rest run
// the fastest of the four, whichever schedule and walk it is.
TEST(ScheduleChooser, WithCompressedNodesTheTrialTimesBothWalksUnderEachSchedule) {
    // Seconds a pass: the compressed walk is faster in the wavefront, slower in the megakernel,
    // and the megakernel on binary nodes fastest of all (the 64-instance field on an H200).
    const auto seconds = [](PassSchedule p) {
        return p.megakernel ? (p.compressedWalk ? 0.0086 : 0.0078) : (p.compressedWalk ? 0.0103 : 0.0114);
    };
    ScheduleChooser c;
    c.setKey(3, true);
    const PassSchedule order[] = {{true, false}, {false, false}, {true, true}, {false, true}};
    for (uint32_t pass = 0; pass < 4 * ScheduleChooser::kTrialPassesEach; ++pass) {
        EXPECT_FALSE(c.decided()) << "pass " << pass;
        EXPECT_EQ(c.walkChoice(), "");
        const PassSchedule next = c.next();
        EXPECT_EQ(next.megakernel, order[pass % 4].megakernel) << "pass " << pass;
        EXPECT_EQ(next.compressedWalk, order[pass % 4].compressedWalk) << "pass " << pass;
        c.record(next, seconds(next));
    }
    EXPECT_TRUE(c.decided());
    EXPECT_TRUE(c.next().megakernel);
    EXPECT_FALSE(c.next().compressedWalk);
    EXPECT_EQ(c.choice(), "megakernel");
    EXPECT_EQ(c.walkChoice(), "binary");
    // Each schedule's rate is that of its faster walk.
    EXPECT_DOUBLE_EQ(c.megakernelRate(), 1.0 / 0.0078);
    EXPECT_DOUBLE_EQ(c.wavefrontRate(), 1.0 / 0.0103);

    // Where the compressed walk wins in the megakernel, it is chosen.
    c.setKey(4, true);
    while (!c.decided()) {
        const PassSchedule next = c.next();
        c.record(next, next.compressedWalk && next.megakernel ? 0.0060 : seconds(next));
    }
    EXPECT_TRUE(c.next().megakernel);
    EXPECT_TRUE(c.next().compressedWalk);
    EXPECT_EQ(c.walkChoice(), "compressed");
}

}  // namespace
}  // namespace pt
