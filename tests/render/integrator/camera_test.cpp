#include "render/integrator/camera.h"

#include <gtest/gtest.h>

#include "render/lights/environment.h"
#include "render/scene/scene.h"

namespace pt {
namespace {

TEST(Camera, PinholeRaysLeaveTheEyeThroughThePixel) {
    Camera camera;
    camera.position = {1, 2, 3};
    camera.lookAt = {1, 2, -7};
    camera.verticalFovDegrees = 90;
    const RenderCamera rc = makeRenderCamera(camera, 200, 100);
    const Ray centre = generateCameraRay(rc, 200, 100, 100, 50, {0.0f, 0.0f}, {0.3f, 0.8f});
    EXPECT_EQ(centre.origin, camera.position);
    EXPECT_NEAR(centre.direction.z, -1.0f, 1e-6f);
    // Top-left corner: fov 90 puts the top edge at 45 degrees; aspect 2 the left edge at atan(2).
    const Ray corner = generateCameraRay(rc, 200, 100, 0, 0, {0.0f, 0.0f}, {0.5f, 0.5f});
    EXPECT_NEAR(corner.direction.y / -corner.direction.z, 1.0f, 1e-5f);
    EXPECT_NEAR(corner.direction.x / -corner.direction.z, -2.0f, 1e-5f);
}

// Thin lens: every ray through a pixel meets the others on the plane of focus, wherever it
// leaves the aperture, and the aperture is a disk of the given radius.
TEST(Camera, ThinLensRaysConvergeOnThePlaneOfFocus) {
    Camera camera;
    camera.position = {0, 0, 0};
    camera.lookAt = {0, 0, -1};
    camera.apertureRadius = 0.25f;
    camera.focusDistance = 7.0f;
    const RenderCamera rc = makeRenderCamera(camera, 64, 64);
    const Ray pinhole = generateCameraRay(rc, 64, 64, 10, 50, {0.5f, 0.5f}, {0.5f, 0.5f});
    const Vec3 focus = pinhole.origin + pinhole.direction * (7.0f / -pinhole.direction.z);
    for (float u : {0.0f, 0.1f, 0.5f, 0.9f}) {
        for (float v : {0.05f, 0.5f, 0.95f}) {
            const Ray r = generateCameraRay(rc, 64, 64, 10, 50, {0.5f, 0.5f}, {u, v});
            EXPECT_LE(length(r.origin), 0.25f + 1e-6f);
            EXPECT_NEAR(r.origin.z, 0.0f, 1e-6f);
            const Vec3 p = r.origin + r.direction * ((-7.0f - r.origin.z) / r.direction.z);
            EXPECT_NEAR(length(p - focus), 0.0f, 1e-4f) << u << "," << v;
        }
    }
}

TEST(Camera, FocusDistanceDefaultsToTheLookAtPointAndUpMayBeParallel) {
    Camera camera;
    camera.position = {0, 5, 0};
    camera.lookAt = {0, 0, 0};
    camera.up = {0, 1, 0};  // parallel to the view: a perpendicular is chosen
    const RenderCamera rc = makeRenderCamera(camera, 8, 8);
    EXPECT_FLOAT_EQ(rc.focusDistance, 5.0f);
    EXPECT_TRUE(isFinite(rc.right));
    EXPECT_NEAR(dot(rc.right, rc.forward), 0.0f, 1e-6f);
}

TEST(Environment, EquirectangularMappingFollowsTheDocumentedConvention) {
    auto uv = [](Vec3 d, float rotation = 0.0f) { return directionToEquirect(d, rotation); };
    EXPECT_NEAR(uv({0, 0, -1}).x, 0.5f, 1e-6f);
    EXPECT_NEAR(uv({1, 0, 0}).x, 0.75f, 1e-6f);
    EXPECT_NEAR(uv({-1, 0, 0}).x, 0.25f, 1e-6f);
    EXPECT_NEAR(uv({0, 1, 0}).y, 0.0f, 1e-6f);
    EXPECT_NEAR(uv({0, -1, 0}).y, 1.0f, 1e-6f);
    EXPECT_NEAR(uv({1, 0, 0}).y, 0.5f, 1e-6f);
    // Rotating the map by +90 degrees about +Y brings what was at -Z to +X.
    EXPECT_NEAR(uv({1, 0, 0}, 0.5f * kPi).x, 0.5f, 1e-6f);
}

}  // namespace
}  // namespace pt
