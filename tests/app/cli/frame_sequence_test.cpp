// Frame ranges and the file names of a sequence's frames (app/cli/frame_sequence.h).
#include "cli/frame_sequence.h"

#include <gtest/gtest.h>

#include "cli/cli_options.h"

namespace pt::cli {
namespace {

TEST(FrameSequence, RangesListTheirFrames) {
    EXPECT_EQ(parseFrameRange("3:5").frames(), (std::vector<int64_t>{3, 4, 5}));
    EXPECT_EQ(parseFrameRange("0:10:4").frames(), (std::vector<int64_t>{0, 4, 8}));
    EXPECT_EQ(parseFrameRange("-2:-2").frames(), (std::vector<int64_t>{-2}));
    for (const char* bad : {"5", "5:3", "0:4:0", "1:x", "1:2:3:4", ":4", "1.5:3"})
        EXPECT_THROW(parseFrameRange(bad), UsageError) << bad;
}

TEST(FrameSequence, HashesBecomeTheZeroPaddedFrameNumber) {
    EXPECT_EQ(framePath("out_####.exr", 7), "out_0007.exr");
    EXPECT_EQ(framePath("out_#.exr", 1234), "out_1234.exr") << "wider numbers are not cut";
    EXPECT_EQ(framePath("renders/f##_a.png", -3), "renders/f-3_a.png");
    EXPECT_EQ(framePath("f####.exr", -3), "f-003.exr");
    EXPECT_THROW(framePath("out.exr", 1), UsageError);
    EXPECT_THROW(framePath("a##_b##.exr", 1), UsageError);
    EXPECT_TRUE(hasFrameNumber("a#"));
    EXPECT_FALSE(hasFrameNumber("a"));
}

}  // namespace
}  // namespace pt::cli
