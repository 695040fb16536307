// The error metrics of converge, stress and the editor's live curve, against values worked out
// by hand.
#include "render/util/image_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace pt {
namespace {

// Two pixels, RGBA; alpha values differ on purpose: they must not count.
const std::vector<float> kReference = {1.0f, 0.0f, 2.0f, 1.0f, 0.5f, 0.5f, 0.0f, 1.0f};
const std::vector<float> kImage = {1.1f, 0.1f, 2.0f, 0.0f, 0.5f, 0.3f, 0.0f, 7.0f};

TEST(ImageError, MatchesHandComputedValues) {
    // Differences: 0.1, 0.1, 0, 0, -0.2, 0 over six colour values.
    const ImageError e = imageError(kImage, kReference);
    const double rel = (0.01 / 1.01 + 0.01 / 0.01 + 0.04 / 0.26) / 6.0;  // (x-r)^2 / (r^2 + 0.01)
    EXPECT_NEAR(e.relMse, rel, 1e-6);
    EXPECT_NEAR(e.rmse, std::sqrt((0.01 + 0.01 + 0.04) / 6.0), 1e-6);
    const double mape = 100.0 * (0.1 / 1.01 + 0.1 / 0.01 + 0.2 / 0.51) / 6.0;  // |x-r| / (|r| + 0.01)
    EXPECT_NEAR(e.mape, mape, 1e-4);
}

TEST(ImageError, IsZeroForTheReferenceItselfAndSizesMustMatch) {
    const ImageError e = imageError(kReference, kReference);
    EXPECT_EQ(e.relMse, 0.0);
    EXPECT_EQ(e.rmse, 0.0);
    EXPECT_EQ(e.mape, 0.0);
    EXPECT_THROW(imageError(kImage, std::vector<float>(4, 0.0f)), std::invalid_argument);
    EXPECT_THROW(imageError(std::vector<float>(3), std::vector<float>(3)), std::invalid_argument);
}

TEST(ImageError, NoiseLevelIsTheExpectedErrorOfThatVariance) {
    const std::vector<float> variance = {0.01f, 0.0f, 0.04f, 9.0f, 0.0f, 0.0f, 0.01f, 9.0f};
    const NoiseLevel n = noiseLevel(variance, kReference);
    EXPECT_NEAR(n.relMse, (0.01 / 1.01 + 0.04 / 4.01 + 0.01 / 0.01) / 6.0, 1e-6);
    EXPECT_NEAR(n.rmse, std::sqrt(0.06 / 6.0), 1e-6);
}

TEST(ImageError, ChannelMeansAndFiniteness) {
    const std::vector<double> means = channelMeans(kReference);
    EXPECT_DOUBLE_EQ(means[0], 0.75);
    EXPECT_DOUBLE_EQ(means[1], 0.25);
    EXPECT_DOUBLE_EQ(means[2], 1.0);
    EXPECT_TRUE(allFinite(kImage));
    std::vector<float> nan = kImage;
    nan[3] = std::numeric_limits<float>::quiet_NaN();  // alpha: ignored
    EXPECT_TRUE(allFinite(nan));
    nan[5] = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(allFinite(nan));
}

}  // namespace
}  // namespace pt
