// pt-render stress: the quick suite passes on the CPU, and each expectation fails when the
// renderer misbehaves (checked on synthetic measurements, since a working renderer cannot
// be made to fail on demand).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "app/cli_runner.h"
#include "pt_render/stress/stress_expectation.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using cli::BatchedImage;
using test::runCli;

// A width x 1 image of `value` everywhere with per-value variance of the mean `variance`.
BatchedImage flatImage(size_t width, float value, float variance) {
    BatchedImage image;
    image.mean.assign(width * 4, value);
    image.varianceOfMean.assign(width * 4, variance);
    for (size_t i = 3; i < image.mean.size(); i += 4) image.mean[i] = 1.0f, image.varianceOfMean[i] = 0.0f;
    image.batches = 4;
    return image;
}

TEST(PtRenderStress, QuickSuitePassesOnTheCpu) {
    const std::string csv = test::tempDir() + "/stress.csv";
    const auto r = runCli("stress --quick --backend cpu --csv " + csv);
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    for (const char* group : {"scale", "geometry", "materials", "lights", "accumulation", "camera"}) {
        EXPECT_NE(r.out.find("\n" + std::string(group) + " "), std::string::npos) << group;
    }
    EXPECT_EQ(r.out.find("FAIL"), std::string::npos) << r.out;
    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header,
              "group,case,backend,nonfinite_samples,error,bound,result,seconds,expectation,note,known_issue");
    size_t rows = 0;
    for (std::string line; std::getline(in, line); ++rows) {
        EXPECT_TRUE(line.find(",pass,") != std::string::npos || line.find(",known,") != std::string::npos)
            << line;
    }
    EXPECT_GE(rows, 20u);
}

TEST(PtRenderStress, AllSaysWhyCudaIsSkippedAndUsageErrorsExit2) {
    const auto all = runCli("stress --quick --backend all --only accumulation");
    EXPECT_EQ(all.exitCode, 0) << all.err;
    EXPECT_NE(all.out.find("1e6 spp of a constant"), std::string::npos) << all.out;
    if (all.out.find(" cuda ") == std::string::npos) {
        EXPECT_NE(all.err.find("cuda skipped: "), std::string::npos) << all.err;
    }
    EXPECT_EQ(runCli("stress --only no-such-case").exitCode, 2);
    EXPECT_EQ(runCli("stress --quick extra").exitCode, 2);
    EXPECT_EQ(runCli("stress --frobnicate").exitCode, 2);
    EXPECT_EQ(runCli("stress --backend vulkan").exitCode, 1);
}

TEST(StressExpectation, MatchingImagesPassAndABiasIsCaught) {
    const BatchedImage baseline = flatImage(64, 0.5f, 1e-4f);
    EXPECT_TRUE(cli::matchesBaseline(flatImage(64, 0.505f, 1e-4f), baseline, 3.0).passed());
    // A 20% leak: bias^2 / (r^2 + 0.01) = 0.01 / 0.26 against noise 2e-4 / 0.26.
    const cli::StressOutcome leak = cli::matchesBaseline(flatImage(64, 0.6f, 1e-4f), baseline, 3.0);
    EXPECT_FALSE(leak.passed());
    EXPECT_NEAR(leak.error, 0.01 / 0.26, 1e-5);
    EXPECT_NEAR(leak.bound, 3.0 * 2e-4 / 0.26, 1e-6);
    BatchedImage withNan = flatImage(64, 0.5f, 1e-4f);
    withNan.nonfiniteSamples = 1;
    EXPECT_FALSE(cli::matchesBaseline(withNan, baseline, 3.0).passed());
}

TEST(StressExpectation, ConstantsAndEnergyBoundsFailWhenBroken) {
    // A furnace that gains 1% of energy (e.g. a BSDF whose sampling and pdf disagree).
    EXPECT_FALSE(cli::meanEquals(flatImage(256, 1.01f, 1e-6f), {1, 1, 1}, 1e-3).passed());
    EXPECT_TRUE(cli::meanEquals(flatImage(256, 1.0005f, 1e-6f), {1, 1, 1}, 1e-3).passed());
    // Accumulation in float drifts by far more than 1e-5 over a million samples.
    EXPECT_FALSE(cli::meanEquals(flatImage(1, 0.7001f, 0.0f), {0.7, 0.7, 0.7}, 1e-5).passed());
    EXPECT_TRUE(
        cli::meanEquals(flatImage(1, 0.7f, 0.0f), {double(0.7f), double(0.7f), double(0.7f)}, 1e-5).passed());
    // Energy <= 1: the noise of the mean (4 sigma = 4 * sqrt(1e-4 / 256) = 0.0025) is allowed,
    // a gain of 1% is not.
    EXPECT_TRUE(cli::meanWithin(flatImage(256, 1.002f, 1e-4f), {0.2, 0.2, 0.2}, {1, 1, 1}, 0.0).passed());
    EXPECT_FALSE(cli::meanWithin(flatImage(256, 1.01f, 1e-4f), {0.2, 0.2, 0.2}, {1, 1, 1}, 0.0).passed());
    EXPECT_FALSE(cli::meanWithin(flatImage(256, 0.0f, 0.0f), {0.2, 0.2, 0.2}, {1, 1, 1}, 0.0).passed());
}

TEST(StressExpectation, ARefusalMustNameFileAndElement) {
    EXPECT_TRUE(
        cli::loadRefused(false, "a.json: objects[0].file: a.obj: line 3: bad", {"a.obj", "line 3"}).passed());
    EXPECT_FALSE(cli::loadRefused(true, "", {"a.obj"}).passed());  // loaded NaN without a word
    const cli::StressOutcome vague = cli::loadRefused(false, "cannot load", {"a.obj", "line 3"});
    EXPECT_FALSE(vague.passed());
    EXPECT_NE(vague.note.find("a.obj"), std::string::npos);
}

}  // namespace
}  // namespace pt
