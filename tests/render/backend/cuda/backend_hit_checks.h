#pragma once
// What GPU tests compare between two backends (or one backend before and after an edit): the
// hits of the same rays, their images, and a device buffer's size by its name in
// deviceMemoryByBuffer().
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "render/backend/backend.h"
#include "render/bvh/bvh_test_util.h"

namespace pt::test {

// Closest and any hits of `rays` in `a` and `b` agree: whether each ray hits, and for closest
// hits the instance and t, bit for bit (ties between coincident triangles may pick either
// primitive). At least a fifth of the rays must hit, else nothing was tested.
inline void expectSameHits(Backend& a, Backend& b, const std::vector<Ray>& rays, const char* what) {
    for (const bool anyHit : {false, true}) {
        std::vector<Hit> ha, hb;
        a.traceRays(rays, anyHit, 1, &ha);
        b.traceRays(rays, anyHit, 1, &hb);
        ASSERT_EQ(ha.size(), hb.size());
        size_t mismatches = 0, hits = 0;
        for (size_t i = 0; i < ha.size(); ++i) {
            hits += ha[i].valid();
            mismatches += ha[i].valid() != hb[i].valid() ||
                          (!anyHit && (ha[i].instance != hb[i].instance || ha[i].t != hb[i].t));
        }
        EXPECT_EQ(mismatches, 0u) << what << (anyHit ? ", any hit" : ", closest hit");
        EXPECT_GT(hits, ha.size() / 5) << what << ": too few rays hit to test anything";
    }
}

// `count` rays from random points of the box [lo, hi] through others: every direction.
inline std::vector<Ray> raysInBox(uint32_t count, uint32_t seed, Vec3 lo, Vec3 hi) {
    Rng rng(seed);
    std::vector<Ray> rays;
    for (uint32_t i = 0; i < count; ++i) rays.push_back(randomRay(rng, lo, hi));
    return rays;
}

// The largest difference of any channel of any pixel between `a`'s and `b`'s mean images
// (infinity where their sizes differ).
inline float largestBeautyDifference(const Backend& a, const Backend& b) {
    std::vector<float> pa, pb;
    a.readBeauty(pa);
    b.readBeauty(pb);
    if (pa.size() != pb.size()) return INFINITY;
    float worst = 0.0f;
    for (size_t i = 0; i < pa.size(); ++i) worst = std::max(worst, std::fabs(pa[i] - pb[i]));
    return worst;
}

inline uint64_t bufferBytes(const Backend& backend, const std::string& name) {
    for (const auto& [buffer, bytes] : backend.deviceMemoryByBuffer())
        if (buffer == name) return bytes;
    ADD_FAILURE() << "no buffer named " << name;
    return 0;
}

}  // namespace pt::test
