#include "editor/step_passes.h"

#include <gtest/gtest.h>

namespace pt::editor {
namespace {

TEST(AutoPassesPerStep, TheFirstFrameAfterAnEditTakesOnePass) {
    EXPECT_EQ(autoPassesPerStep(0.0, 0), 1u);
    // However fast the last passes were: the accumulation was reset, the edit's frame comes first.
    EXPECT_EQ(autoPassesPerStep(1e-4, 0), 1u);
}

TEST(AutoPassesPerStep, LaterStepsFillAboutADisplayFrame) {
    EXPECT_EQ(autoPassesPerStep(1.0 / 240.0, 1), 4u);             // 4.2 ms a pass: four fit in 16.7 ms
    EXPECT_EQ(autoPassesPerStep(kAutoStepSeconds / 2.5, 7), 2u);  // rounded down, never past the budget
    EXPECT_EQ(autoPassesPerStep(0.5, 3), 1u);                     // slow passes: one a step, never zero
    EXPECT_EQ(autoPassesPerStep(1e-6, 3), kMaxAutoPasses);        // bounded however fast
    EXPECT_EQ(autoPassesPerStep(0.0, 3), 1u);                     // not measured yet
}

}  // namespace
}  // namespace pt::editor
