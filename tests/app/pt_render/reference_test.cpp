// pt-render reference: a float EXR with its own noise estimate in the header.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>

#include "app/cli_runner.h"
#include "assets/image/image_metadata.h"
#include "assets/image/image_write.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::runCli;

std::string cornell() { return "'" + test::projectPath("scenes/cornell.json") + "'"; }

TEST(PtRenderReference, WritesExrWithNoiseMetadata) {
    PT_REQUIRE_OIIO();
    const std::string exr = test::tempDir() + "/ref.exr";
    const auto r =
        runCli("reference " + cornell() + " -o " + exr + " --spp 30 --batches 4 --size 16x12 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, exr + "\n");
    uint32_t w = 0, h = 0;
    const std::vector<float> rgba = readImageRgba(exr, w, h);
    EXPECT_EQ(w, 16u);
    EXPECT_EQ(h, 12u);
    std::map<std::string, std::string> meta;
    for (const auto& [key, value] : readImageMetadata(exr)) meta[key] = value;
    EXPECT_EQ(meta["pt:spp"], "32");  // rounded up to 4 equal batches of 8
    EXPECT_EQ(meta["pt:batches"], "4");
    EXPECT_EQ(meta["pt:backend"], "cpu");
    const double relMse = std::strtod(meta["pt:noise_relmse"].c_str(), nullptr);
    const double rmse = std::strtod(meta["pt:noise_rmse"].c_str(), nullptr);
    // A Cornell box at 32 spp is visibly noisy, and far from pure noise.
    EXPECT_GT(relMse, 1e-4);
    EXPECT_LT(relMse, 1.0);
    EXPECT_GT(rmse, 1e-3);
    EXPECT_EQ(meta["pt:nonfinite_samples"], "0");
}

TEST(PtRenderReference, MoreSamplesMeanLessNoise) {
    PT_REQUIRE_OIIO();
    const auto noiseOf = [](uint32_t spp) {
        const std::string exr = test::tempDir() + "/ref" + std::to_string(spp) + ".exr";
        const auto r = runCli("reference " + cornell() + " -o " + exr + " --spp " + std::to_string(spp) +
                              " --size 16x16 --quiet");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        for (const auto& [key, value] : readImageMetadata(exr)) {
            if (key == "pt:noise_rmse") return std::strtod(value.c_str(), nullptr);
        }
        return -1.0;
    };
    const double low = noiseOf(16), high = noiseOf(256);
    // RMSE falls as 1/sqrt(spp): 4x for 16x the samples; the estimate is itself noisy.
    EXPECT_GT(low / high, 2.0);
    EXPECT_LT(low / high, 8.0);
}

TEST(PtRenderReference, BadUsageExits2AndBadInput1) {
    const std::string out = " -o " + test::tempDir() + "/x.exr";
    EXPECT_EQ(runCli("reference " + cornell() + out).exitCode, 2);         // no --spp
    EXPECT_EQ(runCli("reference " + cornell() + " --spp 8").exitCode, 2);  // no -o
    EXPECT_EQ(runCli("reference " + cornell() + out + " --spp 8 --batches 1").exitCode, 2);
    const auto missing = runCli("reference /nonexistent/s.json" + out + " --spp 8");
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("/nonexistent/s.json"), std::string::npos) << missing.err;
    EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
    const auto folder = runCli("reference " + cornell() + " -o /nonexistent/dir/r.exr --spp 8");
    EXPECT_EQ(folder.exitCode, 1);
    EXPECT_NE(folder.err.find("/nonexistent/dir"), std::string::npos) << folder.err;
}

}  // namespace
}  // namespace pt
