// Ray/sphere test (render/bvh/sphere_intersect.h): basic cases, the origin inside, and the
// precision cases of Ray Tracing Gems ch. 7 (tiny and huge radii, far from the origin),
// against a double-precision reference.
#include "render/bvh/sphere_intersect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace pt {
namespace {

// Double-precision nearest root in (0, inf); false on a miss.
bool referenceSphere(Vec3 o, Vec3 d, Vec4 s, double& t) {
    const double fx = double(o.x) - s.x, fy = double(o.y) - s.y, fz = double(o.z) - s.z;
    const double a = double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
    const double b = -(fx * d.x + fy * d.y + fz * d.z);
    const double c = fx * fx + fy * fy + fz * fz - double(s.w) * s.w;
    const double disc = b * b - a * c;
    if (disc < 0) return false;
    const double r0 = (b - std::sqrt(disc)) / a, r1 = (b + std::sqrt(disc)) / a;
    t = r0 > 0 ? r0 : r1;
    return t > 0;
}

TEST(SphereIntersect, FromOutside) {
    float t = 0;
    ASSERT_TRUE(intersectSphere(Ray{{0, 0, 5}, {0, 0, -1}, kInf}, {0, 0, 0, 1}, t));
    EXPECT_FLOAT_EQ(t, 4.0f);
    ASSERT_TRUE(intersectSphere(Ray{{0, 0, 5}, {0, 0, -2}, kInf}, {0, 0, 0, 1}, t));
    EXPECT_FLOAT_EQ(t, 2.0f) << "t in the unnormalised direction's units";
}

TEST(SphereIntersect, FromInsideReturnsTheFarHit) {
    float t = 0;
    ASSERT_TRUE(intersectSphere(Ray{{0, 0, 0}, {0, 0, -1}, kInf}, {0, 0, 0, 1}, t));
    EXPECT_FLOAT_EQ(t, 1.0f);
    ASSERT_TRUE(intersectSphere(Ray{{0, 0, 0.5f}, {0, 0, 1}, kInf}, {0, 0, 0, 1}, t));
    EXPECT_FLOAT_EQ(t, 0.5f);
}

TEST(SphereIntersect, MissesBehindAsideAndBeyondTMax) {
    float t = 0;
    EXPECT_FALSE(intersectSphere(Ray{{0, 0, 5}, {0, 0, 1}, kInf}, {0, 0, 0, 1}, t));
    EXPECT_FALSE(intersectSphere(Ray{{0, 2, 5}, {0, 0, -1}, kInf}, {0, 0, 0, 1}, t));
    EXPECT_FALSE(intersectSphere(Ray{{0, 0, 5}, {0, 0, -1}, 4.0f}, {0, 0, 0, 1}, t));
    EXPECT_FALSE(intersectSphere(Ray{{0, 0, 5}, {0, 0, 0}, kInf}, {0, 0, 0, 1}, t)) << "zero direction";
}

TEST(SphereIntersect, TinyRadius) {
    float t = 0;
    ASSERT_TRUE(intersectSphere(Ray{{0, 0, 1}, {0, 0, -1}, kInf}, {0, 0, 0, 1e-4f}, t));
    EXPECT_NEAR(t, 1.0f - 1e-4f, 1e-7f);
    ASSERT_TRUE(intersectSphere(Ray{{0, 0, 1e3f}, {0, 0, -1}, kInf}, {0, 0, 0, 1e-4f}, t))
        << "tiny sphere far along the ray: the naive b^2 - ac discriminant cancels to garbage here";
    EXPECT_NEAR(t, 1e3f - 1e-4f, 1e-4f);
    // Slightly off-centre: still inside the tiny radius.
    ASSERT_TRUE(intersectSphere(Ray{{0.5e-4f, 0, 1e3f}, {0, 0, -1}, kInf}, {0, 0, 0, 1e-4f}, t));
    EXPECT_FALSE(intersectSphere(Ray{{1.5e-4f, 0, 1e3f}, {0, 0, -1}, kInf}, {0, 0, 0, 1e-4f}, t));
}

TEST(SphereIntersect, HugeRadius) {
    const Vec4 huge{0, 0, -100001.0f, 1e5f};  // surface at z = -1
    float t = 0;
    ASSERT_TRUE(intersectSphere(Ray{{0, 0, 0}, {0, 0, -1}, kInf}, huge, t));
    EXPECT_NEAR(t, 1.0f, 1e-2f);  // the centre itself is only known to ~0.004 in float
    ASSERT_TRUE(intersectSphere(Ray{{0, 0, -2}, {0, 0, 1}, kInf}, huge, t)) << "from inside";
    EXPECT_NEAR(t, 1.0f, 1e-2f);
}

TEST(SphereIntersect, FarFromTheWorldOrigin) {
    const Vec4 tiny{1e5f, -1e5f, 1e5f, 1e-4f}, unit{1e5f, -1e5f, 1e5f, 1.0f};
    float t = 0;
    ASSERT_TRUE(intersectSphere(Ray{{1e5f, -1e5f, 1e5f + 1.0f}, {0, 0, -1}, kInf}, tiny, t));
    EXPECT_NEAR(t, 1.0f - 1e-4f, 1e-6f);
    ASSERT_TRUE(intersectSphere(Ray{{1e5f, -1e5f, 1e5f + 8.0f}, {0, 0, -1}, kInf}, unit, t));
    EXPECT_FLOAT_EQ(t, 7.0f);
    ASSERT_TRUE(intersectSphere(Ray{{1e5f, -1e5f, 1e5f}, {0, 1, 0}, kInf}, unit, t)) << "inside";
    EXPECT_FLOAT_EQ(t, 1.0f);
}

// Random spheres of radius 1e-4 .. 1e5 at up to 1e5 from the origin; origins well outside
// (1.5 r .. 10 r) or well inside (< 0.5 r); agreement with double away from grazing rays.
TEST(SphereIntersect, MatchesDoubleReferenceOverScales) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    auto unit = [&] {
        const float z = 2 * u01(rng) - 1, phi = 2 * kPi * u01(rng), r = std::sqrt(1 - z * z);
        return Vec3{r * std::cos(phi), r * std::sin(phi), z};
    };
    int checked = 0, hits = 0;
    for (int i = 0; i < 200000; ++i) {
        const float radius = std::pow(10.0f, -4.0f + 9.0f * u01(rng));
        const Vec3 center = unit() * (1e5f * u01(rng));
        const bool inside = u01(rng) < 0.25f;
        const float dist = radius * (inside ? 0.5f * u01(rng) : 1.5f + 8.5f * u01(rng));
        const Vec3 origin = center + unit() * dist;
        const Vec3 dir = unit() * std::pow(10.0f, 2.0f * u01(rng) - 1.0f);
        const Vec4 s{center.x, center.y, center.z, radius};
        double tRef = 0;
        const bool ref = referenceSphere(origin, dir, s, tRef);
        // Skip rays within 1e-3 of tangency (relative), where a rounding decides.
        const Vec3 f = origin - center;
        const double along = dot(f, dir) / dot(dir, dir);
        const double miss = length(f - dir * float(along));
        if (std::abs(miss - radius) < 1e-3 * radius) continue;
        float t = 0;
        const bool got = intersectSphere(Ray{origin, dir, kInf}, s, t);
        ++checked;
        ASSERT_EQ(got, ref) << "sphere " << i << " radius " << radius;
        if (!got) continue;
        ++hits;
        // Error scale: the coordinates' own precision around the sphere.
        const double scale = (length(f) + radius) / length(dir);
        ASSERT_NEAR(t, tRef, 1e-5 * scale) << "sphere " << i << " radius " << radius;
    }
    EXPECT_GT(checked, 190000);
    EXPECT_GT(hits, 50000);
}

}  // namespace
}  // namespace pt
