// The a-trous weights' host exponential against std::exp.
#include <gtest/gtest.h>

#include <cmath>

#include "render/denoise/atrous_filter.h"

namespace pt {
namespace {

TEST(FastExp, FollowsExpToAHundredThousandthWhereWeightsLive) {
    double worst = 0.0;
    for (float x = -87.0f; x <= 0.0f; x += 0.0137f) {
        const double truth = std::exp(double(x));
        worst = std::max(worst, std::fabs(double(denoise::fastExp(x)) - truth) / truth);
    }
    EXPECT_LT(worst, 1e-5);
    EXPECT_EQ(denoise::fastExp(0.0f), 1.0f);
}

TEST(FastExp, IsZeroForSurfacesThatShareNothing) {
    EXPECT_EQ(denoise::fastExp(denoise::kDisjoint), 0.0f);
    EXPECT_EQ(denoise::fastExp(-100.0f), 0.0f);  // below 2^-126: no denormal weights
    EXPECT_GT(denoise::fastExp(-87.0f), 0.0f);
}

}  // namespace
}  // namespace pt
