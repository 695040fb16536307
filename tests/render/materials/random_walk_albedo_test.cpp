// Chiang et al.'s albedo inversion (random_walk_albedo.h), checked against what it promises: a
// random walk in a semi-infinite, index-matched medium of isotropic scattering with the
// single-scattering albedo the fit gives for A reflects A in all under diffuse light, here
// measured by simulation (independent of the fit: exponential free flights, uniform directions).
#include "render/materials/random_walk_albedo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "chi_square.h"

namespace pt {
namespace {

// The fraction of light entering the half-space z < 0 (sigma_t = 1) at cos(theta) = `mu` (mu <= 0:
// diffuse light, cosine-distributed) that leaves it again, with single-scattering albedo alpha;
// paths are weighted by alpha^bounces, and ended by Russian roulette (unbiased) once faint.
double halfSpaceReflectance(double alpha, double mu, int paths, uint64_t seed) {
    test::Pcg32 rng(seed);
    double reflected = 0.0;
    for (int p = 0; p < paths; ++p) {
        double z = 0.0, dz = mu > 0.0 ? -mu : -std::sqrt(rng.uniform()), weight = 1.0;
        for (int bounce = 0; bounce < 1000000; ++bounce) {
            const double t = -std::log(1.0 - rng.uniform());
            z += dz * t;
            if (z > 0.0) {
                reflected += weight;
                break;
            }
            weight *= alpha;
            if (weight < 0.1) {
                if (rng.uniform() * 0.1 >= weight) break;
                weight = 0.1;
            }
            dz = 2.0 * rng.uniform() - 1.0;  // isotropic: the cosine is uniform
        }
    }
    return reflected / paths;
}

TEST(RandomWalkAlbedo, EndsAndMiddleMapAsTheFitSays) {
    EXPECT_FLOAT_EQ(randomWalkSingleScatterAlbedo(0.0f), 0.0f);
    EXPECT_NEAR(randomWalkSingleScatterAlbedo(1.0f), 1.0f, 2e-3f);
    float last = -1.0f;
    for (int i = 0; i <= 100; ++i) {
        const float alpha = randomWalkSingleScatterAlbedo(i / 100.0f);
        EXPECT_GT(alpha, last) << "increasing";
        last = alpha;
    }
    // s = 1.9 - A + 3.5 (A - 0.8)^2: 4.14 at A = 0, 1.04 at A = 1; sigma_t = 1 / (d s).
    EXPECT_NEAR(randomWalkExtinction(0.0f, 2.0f), 1.0f / (2.0f * 4.14f), 1e-5f);
    EXPECT_NEAR(randomWalkExtinction(1.0f, 0.5f), 1.0f / (0.5f * 1.04f), 1e-5f);
}

// Under diffuse light, as the fit was made: within 0.035 of A (0.002 to 0.005 off up to A = 0.7,
// 0.030 low at A = 0.9: the fit's own error in this index-matched setup). Light arriving along
// the normal goes deeper and comes back less, 0.03 to 0.06 below A: printed, not asserted.
TEST(RandomWalkAlbedo, AHalfSpaceUnderDiffuseLightReflectsTheAlbedoAsked) {
    double worst = 0.0;
    for (double a : {0.1, 0.3, 0.5, 0.7, 0.9}) {
        const double alpha = randomWalkSingleScatterAlbedo(float(a));
        const double diffuse = halfSpaceReflectance(alpha, -1.0, 200000, 18);
        const double normal = halfSpaceReflectance(alpha, 1.0, 100000, 17);
        std::printf("A %.1f: alpha %.4f reflects %.4f under diffuse light, %.4f at normal incidence\n", a,
                    alpha, diffuse, normal);
        worst = std::max(worst, std::fabs(diffuse - a));
        EXPECT_NEAR(diffuse, a, 0.035) << "A " << a;
    }
    std::printf("largest difference from A under diffuse light: %.4f\n", worst);
}

}  // namespace
}  // namespace pt
