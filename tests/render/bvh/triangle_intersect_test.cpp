// Watertight ray/triangle test (render/bvh/triangle_intersect.h): hits, misses, barycentrics,
// range, two-sidedness, degenerate input. Watertightness itself: watertight_test.cpp.
#include "render/bvh/triangle_intersect.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

const Vec3 kP0{0, 0, 0}, kP1{1, 0, 0}, kP2{0, 1, 0};

TEST(TriangleIntersect, HitGivesDistanceAndBarycentrics) {
    const Ray ray{{0.25f, 0.5f, 2.0f}, {0, 0, -1}, kInf};
    float t = 0, u = 0, v = 0;
    ASSERT_TRUE(intersectTriangle(ray, kP0, kP1, kP2, t, u, v));
    EXPECT_FLOAT_EQ(t, 2.0f);
    EXPECT_FLOAT_EQ(u, 0.25f);  // weight of p1 = (1, 0, 0)
    EXPECT_FLOAT_EQ(v, 0.5f);   // weight of p2 = (0, 1, 0)
}

TEST(TriangleIntersect, DirectionNeedNotBeUnit) {
    const Ray ray{{0.25f, 0.25f, 3.0f}, {0, 0, -4}, kInf};
    float t = 0, u = 0, v = 0;
    ASSERT_TRUE(intersectTriangle(ray, kP0, kP1, kP2, t, u, v));
    EXPECT_FLOAT_EQ(t, 0.75f);
}

TEST(TriangleIntersect, TwoSided) {
    float t = 0, u = 0, v = 0;
    EXPECT_TRUE(intersectTriangle(Ray{{0.2f, 0.2f, 1}, {0, 0, -1}, kInf}, kP0, kP1, kP2, t, u, v));
    EXPECT_TRUE(intersectTriangle(Ray{{0.2f, 0.2f, -1}, {0, 0, 1}, kInf}, kP0, kP1, kP2, t, u, v));
    EXPECT_TRUE(intersectTriangle(Ray{{0.2f, 0.2f, 1}, {0, 0, -1}, kInf}, kP0, kP2, kP1, t, u, v));
    EXPECT_FLOAT_EQ(t, 1.0f);
}

TEST(TriangleIntersect, MissesOutsideBehindAndBeyondTMax) {
    float t = 0, u = 0, v = 0;
    EXPECT_FALSE(intersectTriangle(Ray{{0.6f, 0.6f, 1}, {0, 0, -1}, kInf}, kP0, kP1, kP2, t, u, v));
    EXPECT_FALSE(intersectTriangle(Ray{{0.2f, 0.2f, 1}, {0, 0, 1}, kInf}, kP0, kP1, kP2, t, u, v));
    EXPECT_FALSE(intersectTriangle(Ray{{0.2f, 0.2f, 1}, {0, 0, -1}, 1.0f}, kP0, kP1, kP2, t, u, v))
        << "tMax is exclusive";
    EXPECT_TRUE(intersectTriangle(Ray{{0.2f, 0.2f, 1}, {0, 0, -1}, std::nextafter(1.0f, 2.0f)}, kP0, kP1, kP2,
                                  t, u, v));
    EXPECT_FALSE(intersectTriangle(Ray{{0.2f, 0.2f, 0}, {0, 0, -1}, kInf}, kP0, kP1, kP2, t, u, v))
        << "t = 0 is excluded";
}

TEST(TriangleIntersect, EdgesAndVerticesAreInside) {
    float t = 0, u = 0, v = 0;
    EXPECT_TRUE(intersectTriangle(Ray{{0.5f, 0, 1}, {0, 0, -1}, kInf}, kP0, kP1, kP2, t, u, v));
    EXPECT_TRUE(intersectTriangle(Ray{{0.5f, 0.5f, 1}, {0, 0, -1}, kInf}, kP0, kP1, kP2, t, u, v));
    EXPECT_TRUE(intersectTriangle(Ray{{1, 0, 1}, {0, 0, -1}, kInf}, kP0, kP1, kP2, t, u, v));
    EXPECT_FLOAT_EQ(u, 1.0f);
    EXPECT_FLOAT_EQ(v, 0.0f);
}

TEST(TriangleIntersect, RayInThePlaneAndDegenerateTrianglesMiss) {
    float t = 0, u = 0, v = 0;
    EXPECT_FALSE(intersectTriangle(Ray{{-1, 0.2f, 0}, {1, 0, 0}, kInf}, kP0, kP1, kP2, t, u, v));
    EXPECT_FALSE(intersectTriangle(Ray{{0.5f, 0.5f, 1}, {0, 0, -1}, kInf}, kP0, kP1, {2, 0, 0}, t, u, v))
        << "collinear vertices";
    EXPECT_FALSE(intersectTriangle(Ray{{0, 0, 1}, {0, 0, -1}, kInf}, kP0, kP0, kP0, t, u, v));
}

TEST(TriangleIntersect, BarycentricsReconstructTheHitPoint) {
    const Vec3 p0{1.5f, -2, 3}, p1{-0.5f, 4, 1}, p2{2, 1, -3};
    uint32_t hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const float a = (float(i % 37) + 0.5f) / 38.0f, b = (float(i % 23) + 0.5f) / 24.0f * (1.0f - a);
        const Vec3 target = p0 * (1.0f - a - b) + p1 * a + p2 * b;
        const Vec3 origin{float(i % 7) - 3.0f, 5.0f, float(i % 5)};
        float t = 0, u = 0, v = 0;
        if (!intersectTriangle(Ray{origin, target - origin, kInf}, p0, p1, p2, t, u, v)) continue;
        ++hits;
        const Vec3 onRay = origin + (target - origin) * t;
        const Vec3 fromBary = p0 * (1.0f - u - v) + p1 * u + p2 * v;
        EXPECT_NEAR(t, 1.0f, 1e-5f);
        EXPECT_NEAR(length(onRay - fromBary), 0.0f, 1e-4f);
    }
    EXPECT_EQ(hits, 1000u);
}

}  // namespace
}  // namespace pt
