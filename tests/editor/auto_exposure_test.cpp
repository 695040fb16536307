// Auto exposure (editor/auto_exposure.h): the log-average luminance of the lit pixels to 0.18.
#include "editor/auto_exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace pt::editor {
namespace {

std::vector<float> image(std::initializer_list<float> greys) {
    std::vector<float> rgba;
    for (const float g : greys) rgba.insert(rgba.end(), {g, g, g, 1.0f});
    return rgba;
}

TEST(AutoExposure, BringsTheLogAverageToMiddleGrey) {
    EXPECT_NEAR(autoExposureStops(image({0.18f, 0.18f})), 0.0f, 1e-5f);
    EXPECT_NEAR(autoExposureStops(image({0.72f})), -2.0f, 1e-5f);
    // A sunlit scene in physical units: about 2000 (cd/m^2) a pixel.
    EXPECT_NEAR(autoExposureStops(image({2000.0f})), std::log2(0.18f / 2000.0f), 1e-4f);
    // The log average, not the mean: 0.045 and 0.72 average (in logs) to 0.18.
    EXPECT_NEAR(autoExposureStops(image({0.045f, 0.72f})), 0.0f, 1e-5f);
}

TEST(AutoExposure, LeavesOutBlackAndNonFinitePixelsAndStaysBounded) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NEAR(autoExposureStops(image({0.72f, 0.0f, 0.0f, inf, nan})), -2.0f, 1e-5f);
    EXPECT_EQ(autoExposureStops(image({0.0f, 0.0f})), 0.0f) << "nothing lit: no change";
    EXPECT_EQ(autoExposureStops({}), 0.0f);
    EXPECT_EQ(autoExposureStops(image({1e-30f})), kMaxAutoExposureStops);
}

}  // namespace
}  // namespace pt::editor
