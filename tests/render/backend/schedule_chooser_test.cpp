#include "render/backend/schedule_chooser.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

// Runs a trial where a megakernel pass takes `megakernel` seconds and a wavefront pass
// `wavefront` (the first pass of each twice as long: its warm-up), and returns the passes run.
int runTrial(ScheduleChooser& c, double megakernel, double wavefront) {
    int passes = 0, megakernelRuns = 0, wavefrontRuns = 0;
    while (!c.decided()) {
        const bool m = c.nextIsMegakernel();
        int& runs = m ? megakernelRuns : wavefrontRuns;
        c.record(m, (m ? megakernel : wavefront) * (runs == 0 ? 2.0 : 1.0));
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
        const bool megakernel = c.nextIsMegakernel();
        EXPECT_EQ(megakernel, pass % 2 == 0) << "the schedules take turns, pass " << pass;
        c.record(megakernel, megakernel ? 0.010 : 0.004);
    }
    EXPECT_TRUE(c.decided());
    EXPECT_FALSE(c.nextIsMegakernel());
    EXPECT_EQ(c.choice(), "wavefront");
    EXPECT_DOUBLE_EQ(c.wavefrontRate(), 250.0);
    EXPECT_DOUBLE_EQ(c.megakernelRate(), 100.0);
}

TEST(ScheduleChooser, TheFirstPassesWarmUpDoNotDecide) {
    // The megakernel is faster once warm, though its first pass is slower than the wavefront's.
    ScheduleChooser c;
    c.setKey(7);
    runTrial(c, 0.003, 0.005);
    EXPECT_TRUE(c.nextIsMegakernel());
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

}  // namespace
}  // namespace pt
