// pt-render render --frames: each frame of an animation to its own files, posed at its time,
// resumable with --skip-existing, with clear errors for what cannot be a sequence.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/cli_runner.h"
#include "assets/image/image_read.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::runCli;

// The quad of tests/data/gltf/anim_slide.gltf slides one unit along x in its first second.
std::string slide() { return "'" + test::testDataPath("gltf/anim_slide.gltf") + "'"; }

TEST(RenderSequence, EachFrameIsPosedAtItsTimeAndWrittenToItsFile) {
    PT_REQUIRE_OIIO();  // the frames are EXRs
    const std::string folder = test::tempDir() + "/sequence";
    std::filesystem::create_directories(folder);
    const auto r = runCli("render " + slide() + " --frames 0:24:12 --fps 24 --spp 2 --size 24x24 -o " +
                          folder + "/f_####.exr --png " + folder + "/f_####.png --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* frame : {"0000", "0012", "0024"}) {
        EXPECT_TRUE(std::filesystem::exists(folder + "/f_" + frame + ".exr")) << frame;
        EXPECT_TRUE(std::filesystem::exists(folder + "/f_" + frame + ".png")) << frame;
    }
    EXPECT_NE(r.out.find("f_0012.exr"), std::string::npos) << "prints the paths it wrote";
    // The quad moved between frames 0 and 24 (one unit in a 24-pixel view), and 12 lies between.
    const Texture first = readTextureFile(folder + "/f_0000.png"),
                  last = readTextureFile(folder + "/f_0024.png");
    ASSERT_EQ(first.texels8.size(), last.texels8.size());
    EXPECT_NE(first.texels8, last.texels8);

    // A restarted job leaves finished frames and renders the missing one.
    std::filesystem::remove(folder + "/f_0012.exr");
    const auto again = runCli("render " + slide() + " --frames 0:24:12 --spp 2 --size 24x24 -o " + folder +
                              "/f_####.exr --png " + folder + "/f_####.png --skip-existing");
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_NE(again.err.find("frame 0: done before, skipped"), std::string::npos) << again.err;
    EXPECT_NE(again.err.find("frame 24: done before, skipped"), std::string::npos) << again.err;
    EXPECT_TRUE(std::filesystem::exists(folder + "/f_0012.exr"));
    EXPECT_EQ(again.out.find("f_0000"), std::string::npos) << "frame 0 was not written again";
}

TEST(RenderSequence, WhatCannotBeASequenceFailsWithOneClearLine) {
    const std::string out = test::tempDir() + "/bad.exr";
    const auto expectError = [](const test::CliResult& r, const std::string& words) {
        EXPECT_NE(r.exitCode, 0);
        EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
    };
    expectError(runCli("render " + slide() + " --frames 0:2 -o " + out), "need #### for the frame");
    expectError(runCli("render " + slide() + " --frames 2:0 -o " + test::tempDir() + "/b#.exr"),
                "the last frame is before the first");
    expectError(runCli("render " + slide() + " --fps 30 -o " + out), "apply to --frames");
    expectError(
        runCli("render " + slide() + " --frames 0:1 --animation run -o " + test::tempDir() + "/b#.exr"),
        "no animation \"run\" (the scene has 0 \"slide\")");
    expectError(runCli("render '" + test::projectPath("scenes/cornell.json") +
                       "' --frames 0:1 --size 8x8 -o " + test::tempDir() + "/c#.exr"),
                "the scene has no animation");
}

}  // namespace
}  // namespace pt
