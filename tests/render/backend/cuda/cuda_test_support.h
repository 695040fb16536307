#pragma once
// GPU tests build wherever nvcc exists and run where a CUDA device exists; elsewhere each one
// skips with the reason.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "render/backend/cuda/cuda_device.h"
#include "render/math/ray.h"

#define PT_REQUIRE_CUDA_DEVICE()                                                          \
    do {                                                                                  \
        std::string ptWhy_;                                                               \
        if (!::pt::cuda::deviceAvailable(&ptWhy_)) GTEST_SKIP() << "skipped: " << ptWhy_; \
    } while (0)

namespace pt::test {

// `count` rays from random points of the box centre (0, 1.5, 0) +- `originSpread` heading
// down (-Y), their direction tilted by up to `tilt` in X and Z: rays that meet a scene lying
// around the XZ plane at every angle a camera or a bounce would.
inline std::vector<Ray> downwardRays(uint32_t count, uint32_t seed, Vec3 originSpread, float tilt) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Ray> rays(count);
    for (Ray& r : rays) {
        r.origin = {originSpread.x * u(rng), 1.5f + originSpread.y * u(rng), originSpread.z * u(rng)};
        r.direction = normalize(Vec3(tilt * u(rng), -1.0f, tilt * u(rng)));
        r.tMax = kInf;
    }
    return rays;
}

}  // namespace pt::test
