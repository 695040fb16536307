// Viewport navigation: orbit, pan, dolly and fly as pure functions of a Camera, checked against
// the geometry each promises (editor/camera_controller.h).
#include "editor/camera_controller.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "support/scene_builder.h"

namespace pt::editor {
namespace {

constexpr float kViewport = 600.0f;

Camera testCamera() {
    Camera c;
    c.position = {1, 2, 6};
    c.lookAt = {1, 1, 2};
    c.up = {0, 1, 0};
    c.verticalFovDegrees = 40.0f;
    return c;
}

void expectNear(Vec3 expected, Vec3 actual, float tolerance, const char* what) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << what;
}

float degrees(float radians) { return radians * 180.0f / kPi; }

// Elevation of the eye above the look-at point's horizontal plane.
float elevationDegrees(const Camera& c) {
    const Vec3 toEye = c.position - c.lookAt;
    return degrees(std::asin(toEye.y / length(toEye)));
}

TEST(CameraController, OrbitKeepsTheDistanceAndTheLookAt) {
    const Camera c = testCamera();
    const float distance = length(c.position - c.lookAt);
    const std::pair<float, float> drags[] = {
        {37.0f, 0.0f}, {0.0f, -55.0f}, {-120.0f, 80.0f}, {900.0f, 900.0f}};
    for (const auto& [dx, dy] : drags) {
        const Camera o = orbitCamera(c, dx, dy, kViewport);
        EXPECT_NEAR(length(o.position - o.lookAt), distance, 1e-4f * distance) << dx << ", " << dy;
        expectNear(c.lookAt, o.lookAt, 0.0f, "lookAt");
        EXPECT_EQ(o.verticalFovDegrees, c.verticalFovDegrees);
    }
}

TEST(CameraController, AFullHeightHorizontalDragTurnsHalfWayAroundY) {
    const Camera c = testCamera();
    const Camera o = orbitCamera(c, kViewport, 0.0f, kViewport);
    // 180 degrees about +Y through the look-at point: x and z of the offset flip, y stays.
    const Vec3 offset = c.position - c.lookAt;
    expectNear(c.lookAt + Vec3(-offset.x, offset.y, -offset.z), o.position, 1e-4f, "eye");
    // A quarter of that turns 45 degrees.
    const Camera q = orbitCamera(c, 0.25f * kViewport, 0.0f, kViewport);
    const Vec3 a = normalize(Vec3(offset.x, 0, offset.z));
    const Vec3 qOffset = q.position - q.lookAt;
    const Vec3 b = normalize(Vec3(qOffset.x, 0, qOffset.z));
    EXPECT_NEAR(degrees(std::acos(std::fmin(dot(a, b), 1.0f))), 45.0f, 1e-2f);
    EXPECT_NEAR(qOffset.y, offset.y, 1e-4f);
}

TEST(CameraController, VerticalDragRaisesTheEyeAndStopsShortOfThePole) {
    const Camera c = testCamera();
    const float start = elevationDegrees(c);
    // Dragging down by a sixth of the viewport raises the eye by 30 degrees.
    const Camera up = orbitCamera(c, 0.0f, kViewport / 6.0f, kViewport);
    EXPECT_GT(up.position.y, c.position.y);
    EXPECT_NEAR(elevationDegrees(up), start + 30.0f, 1e-2f);
    // The heading does not change.
    const Vec3 before = c.position - c.lookAt, after = up.position - up.lookAt;
    EXPECT_NEAR(std::atan2(after.x, after.z), std::atan2(before.x, before.z), 1e-4f);

    const Camera top = orbitCamera(c, 0.0f, 10.0f * kViewport, kViewport);
    EXPECT_NEAR(elevationDegrees(top), 89.0f, 1e-2f);
    const Camera bottom = orbitCamera(c, 0.0f, -10.0f * kViewport, kViewport);
    EXPECT_NEAR(elevationDegrees(bottom), -89.0f, 1e-2f);
    // Past the limit, a further drag up changes nothing (no flip over the pole).
    const Camera further = orbitCamera(top, 0.0f, 100.0f, kViewport);
    EXPECT_NEAR(elevationDegrees(further), 89.0f, 1e-2f);
    EXPECT_GT(dot(normalize(Vec3(further.position.x - c.lookAt.x, 0, further.position.z - c.lookAt.z)),
                  normalize(Vec3(before.x, 0, before.z))),
              0.99f);
}

TEST(CameraController, PanMovesEyeAndLookAtTogether) {
    const Camera c = testCamera();
    const Camera p = panCamera(c, 40.0f, -25.0f, kViewport);
    const Vec3 eyeMove = p.position - c.position, targetMove = p.lookAt - c.lookAt;
    expectNear(eyeMove, targetMove, 1e-5f, "same vector");
    EXPECT_GT(length(eyeMove), 0.0f);
    // The move is in the image plane.
    EXPECT_NEAR(dot(eyeMove, normalize(c.lookAt - c.position)), 0.0f, 1e-5f);
}

TEST(CameraController, AFullHeightPanMovesByTheVisibleHeight) {
    const Camera c = testCamera();
    const float d = length(c.lookAt - c.position);
    const float visible = 2.0f * d * std::tan(0.5f * c.verticalFovDegrees * kPi / 180.0f);
    const Camera vertical = panCamera(c, 0.0f, kViewport, kViewport);
    EXPECT_NEAR(length(vertical.lookAt - c.lookAt), visible, 1e-4f * visible);
    const Camera horizontal = panCamera(c, kViewport, 0.0f, kViewport);
    EXPECT_NEAR(length(horizontal.lookAt - c.lookAt), visible, 1e-4f * visible);
    // Dragging right moves the scene with the cursor: the camera goes left.
    const Vec3 right = normalize(cross(c.lookAt - c.position, c.up));
    EXPECT_LT(dot(horizontal.position - c.position, right), 0.0f);
}

TEST(CameraController, DollyScalesTheDistanceAndNeverReachesTheTarget) {
    const Camera c = testCamera();
    const float d = length(c.lookAt - c.position);
    const Camera in = dollyCamera(c, 1.0f);
    EXPECT_NEAR(length(in.lookAt - in.position), 0.85f * d, 1e-5f * d);
    expectNear(c.lookAt, in.lookAt, 0.0f, "lookAt");
    expectNear(normalize(c.lookAt - c.position), normalize(in.lookAt - in.position), 1e-5f, "direction");
    const Camera out = dollyCamera(c, -1.0f);
    EXPECT_NEAR(length(out.lookAt - out.position), d / 0.85f, 1e-5f * d);
    const Camera far = dollyCamera(c, 1000.0f);
    EXPECT_GT(length(far.lookAt - far.position), 0.0f);
    // Still a usable camera: dollying back out from there recovers a finite view.
    const Camera back = dollyCamera(far, -10.0f);
    EXPECT_TRUE(isFinite(back.position));
    EXPECT_GT(length(back.lookAt - back.position), length(far.lookAt - far.position));
}

TEST(CameraController, FlyMovesAlongTheViewDirection) {
    const Camera c = testCamera();
    const Vec3 forward = normalize(c.lookAt - c.position);
    const Camera f = flyCamera(c, 1.0f, 0.0f, 0.0f, 0.5f, 4.0f);
    expectNear(c.position + forward * 2.0f, f.position, 1e-5f, "eye");
    expectNear(c.lookAt + forward * 2.0f, f.lookAt, 1e-5f, "lookAt");
    const Camera up = flyCamera(c, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f);
    expectNear(c.position + Vec3(0, 1, 0), up.position, 1e-5f, "up");
    const Camera right = flyCamera(c, 0.0f, -1.0f, 0.0f, 1.0f, 3.0f);
    expectNear(c.position - normalize(cross(forward, c.up)) * 3.0f, right.position, 1e-5f, "left");
}

TEST(CameraController, FlySpeedCrossesTheSceneInFourSeconds) {
    Scene scene;
    const uint32_t m = test::addMaterial(scene, "m", test::diffuse({0.5f, 0.5f, 0.5f}));
    test::addShape(scene, ObjectKind::Box, test::trs({0, 0, 0}, {0, 0, 0}, {2, 1, 2}), m);
    Vec3 lo, hi;
    scene.worldBounds(lo, hi);
    EXPECT_NEAR(flySpeedFor(scene), length(hi - lo) / 4.0f, 1e-5f);
    EXPECT_NEAR(flySpeedFor(scene), std::sqrt(16.0f + 4.0f + 16.0f) / 4.0f, 1e-4f);
}

}  // namespace
}  // namespace pt::editor
