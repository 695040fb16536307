// Points across instance transforms and the error bounds that ray spawning relies on
// (render/bvh/instance_space.h).
#include "render/bvh/instance_space.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/scene_builder.h"

namespace pt {
namespace {

using test::trs;

RenderInstance instanceAt(const ObjectTransform& transform) {
    RenderInstance inst{};
    inst.objectToWorld = transform.toAffine();
    inst.worldToObject = inverse(inst.objectToWorld);
    return inst;
}

// Object-space y of world point `p`, in double from the same float matrices: the reference
// that taking a point into object space should match to the object's precision.
double objectYInDouble(const RenderInstance& inst, Vec3 p) {
    const Vec3 t = inst.objectToWorld.translation();
    const Vec4& row = inst.worldToObject.rows[1];
    return double(row.x) * (double(p.x) - t.x) + double(row.y) * (double(p.y) - t.y) +
           double(row.z) * (double(p.z) - t.z);
}

// A lamp like the Cornell box's, moved 1e5 from the origin and tilted. Points near its plane,
// taken into object space, must keep their height over it (object y) to the precision of the
// object, not of the world: the Cornell box's lamp hangs one world ulp (1/128) under the
// ceiling there. worldToObject * p + (-R^-1 t) rounds products of size 1e5 before they cancel.
TEST(InstanceSpace, ObjectSpacePointKeepsTheObjectsPrecisionFarFromTheOrigin) {
    const RenderInstance light = instanceAt(trs({1e5f, 1e5f + 0.995f, 1e5f}, {170, 20, 10}, {0.5f, 1, 0.4f}));
    double worst = 0.0, worstNaive = 0.0;
    for (int i = 0; i <= 20; ++i) {
        for (int j = 0; j <= 20; ++j) {
            const Vec3 q{-1.0f + 0.1f * float(i), 0.0f, -1.0f + 0.1f * float(j)};
            const Vec3 world = light.objectToWorld.transformPoint(q);
            const double reference = objectYInDouble(light, world);
            worst = std::max(worst, std::fabs(objectSpacePoint(light, world).y - reference));
            worstNaive =
                std::max(worstNaive, std::fabs(light.worldToObject.transformPoint(world).y - reference));
        }
    }
    EXPECT_LT(worst, 1e-6);
    EXPECT_GT(worstNaive, 1e-3) << "the naive form no longer loses precision: is this test still needed?";
}

// The bound is a few ulps of the coordinates involved: of the world position where the
// translation is large, of the object where the instance is small, never a fixed epsilon.
TEST(InstanceSpace, SurfacePointErrorScalesWithTheCoordinates) {
    const Vec3 unitQuad{1.0f, 0.0f, 1.0f};  // |vertex| of the built-in quad, per axis
    const float ulpAt1e5 = 1.0f / 128.0f;
    const Vec3 far = surfacePointError(instanceAt(trs(Vec3(1e5f))), unitQuad);
    for (int a = 0; a < 3; ++a) {
        EXPECT_GE(far[a], 0.5f * ulpAt1e5) << a;
        EXPECT_LE(far[a], 2.0f * ulpAt1e5) << a;
    }
    const Vec3 near = surfacePointError(instanceAt(trs(Vec3(0.0f), {30, 40, 50})), unitQuad);
    const Vec3 tiny = surfacePointError(instanceAt(trs(Vec3(0.0f), {30, 40, 50}, Vec3(1e-4f))), unitQuad);
    for (int a = 0; a < 3; ++a) {
        EXPECT_GT(near[a], 0.0f) << a;
        EXPECT_LT(near[a], 1e-5f) << a;
        EXPECT_NEAR(tiny[a] / near[a], 1e-4f, 1e-5f) << a;
    }
}

double distanceToLine(Vec3 p, Vec3 a, Vec3 b) {
    const double ax = double(p.x) - a.x, ay = double(p.y) - a.y, az = double(p.z) - a.z;
    const double ex = double(b.x) - a.x, ey = double(b.y) - a.y, ez = double(b.z) - a.z;
    const double cx = ay * ez - az * ey, cy = az * ex - ax * ez, cz = ax * ey - ay * ex;
    return std::sqrt(cx * cx + cy * cy + cz * cz) / std::sqrt(ex * ex + ey * ey + ez * ez);
}

TEST(InstanceSpace, InsetBarycentricsKeepsAMarginInsideTheTriangle) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const auto point = [&] { return Vec3{unit(rng), unit(rng), unit(rng)} * 2.0f - Vec3(1.0f); };
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p0 = point(), p1 = point(), p2 = point();
        const Vec3 e1 = p1 - p0, e2 = p2 - p0;
        const float inradius = length(cross(e1, e2)) / (length(e1) + length(e2) + length(e2 - e1));
        const float margin = inradius * (i % 4 == 0 ? 1.5f : unit(rng) * 0.9f);
        // Points anywhere, on edges and at vertices included.
        Vec3 b{unit(rng), unit(rng), unit(rng)};
        if (i % 3 == 0) b[i % 2] = 0.0f;
        b = b / (b.x + b.y + b.z);
        const Vec3 inside = insetBarycentrics(b, e1, e2, margin);
        ASSERT_TRUE(isFinite(inside));
        EXPECT_NEAR(inside.x + inside.y + inside.z, 1.0f, 1e-5f);
        if (margin >= inradius) {  // no point is that far inside: the centroid
            EXPECT_EQ(inside, Vec3(1.0f / 3.0f));
            continue;
        }
        const Vec3 p = p0 * inside.x + p1 * inside.y + p2 * inside.z;
        const double slack = 1e-5 * (length(e1) + length(e2));
        EXPECT_GE(distanceToLine(p, p1, p2), margin - slack) << i;
        EXPECT_GE(distanceToLine(p, p0, p2), margin - slack) << i;
        EXPECT_GE(distanceToLine(p, p0, p1), margin - slack) << i;
        // A point already that far inside stays where it is.
        EXPECT_EQ(insetBarycentrics(inside, e1, e2, 0.5f * margin), inside) << i;
    }
    // Degenerate triangles (zero area, or a point) give their centroid, never NaN.
    EXPECT_EQ(insetBarycentrics({1, 0, 0}, {1, 0, 0}, {2, 0, 0}, 1e-3f), Vec3(1.0f / 3.0f));
    EXPECT_EQ(insetBarycentrics({1, 0, 0}, Vec3(0.0f), Vec3(0.0f), 0.0f), Vec3(1.0f / 3.0f));
}

}  // namespace
}  // namespace pt
