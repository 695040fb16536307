// Picking through the CPU backend's BVH: what is under a pixel, mapped back to the scene's
// instances and objects, and the focus distance a click on it gives.
#include "editor/picking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "render/integrator/camera.h"
#include "support/scene_builder.h"

namespace pt::editor {
namespace {

using test::addMaterial;
using test::addShape;
using test::diffuse;
using test::trs;

constexpr uint32_t kWidth = 32, kHeight = 16;

// A sphere on the left (object 0) and a box on the right (object 1), seen from +Z.
Scene twoShapes() {
    Scene scene;
    scene.render = {kWidth, kHeight, 2, 1, 0};
    scene.camera.position = {0, 0, 5};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.verticalFovDegrees = 45.0f;
    const uint32_t m = addMaterial(scene, "grey", diffuse({0.5f, 0.5f, 0.5f}));
    addShape(scene, ObjectKind::Sphere, trs({-1.5f, 0, 0}, {0, 0, 0}, {0.5f, 0.5f, 0.5f}), m, "ball");
    addShape(scene, ObjectKind::Box, trs({1.5f, 0, 0}, {0, 0, 0}, {0.5f, 0.5f, 0.5f}), m, "crate");
    return scene;
}

std::unique_ptr<Backend> syncedBackend(const Scene& scene) {
    std::unique_ptr<Backend> backend = createBackend("cpu");
    backend->setToggles(IntegratorToggles{});
    backend->sync(scene, SceneChanges::All);
    return backend;
}

// The image point (pixels, y down) where the world point `p` appears.
Vec2 project(const Scene& scene, Vec3 p) {
    const RenderCamera rc = makeRenderCamera(scene.camera, scene.render.width, scene.render.height);
    const Vec3 d = p - rc.origin;
    const float z = dot(d, rc.forward);
    const float ndcX = dot(d, rc.right) / (lengthSquared(rc.right) * z);
    const float ndcY = dot(d, rc.up) / (lengthSquared(rc.up) * z);
    return {0.5f * (ndcX + 1.0f) * float(scene.render.width),
            0.5f * (1.0f - ndcY) * float(scene.render.height)};
}

TEST(Picking, TheCentreOfEachShapePicksIt) {
    const Scene scene = twoShapes();
    auto backend = syncedBackend(scene);
    for (int32_t i = 0; i < 2; ++i) {
        const Vec2 at = project(scene, scene.instances[size_t(i)].objectToWorld.translation());
        const PickResult hit = pick(*backend, scene, at.x, at.y);
        EXPECT_TRUE(hit.hit()) << scene.instances[size_t(i)].name;
        EXPECT_EQ(hit.instance, i);
        EXPECT_EQ(hit.object, i);
        EXPECT_GT(hit.distance, 4.0f);
        EXPECT_LT(hit.distance, 5.0f);
    }
}

TEST(Picking, TheBackgroundPicksNothing) {
    const Scene scene = twoShapes();
    auto backend = syncedBackend(scene);
    EXPECT_FALSE(pick(*backend, scene, 0.5f, 0.5f).hit());
    EXPECT_FALSE(pick(*backend, scene, float(kWidth) * 0.5f, 0.5f).hit());
    EXPECT_EQ(pick(*backend, scene, 0.5f, 0.5f).object, -1);
    // Outside the image.
    EXPECT_FALSE(pick(*backend, scene, -1.0f, 8.0f).hit());
    EXPECT_FALSE(pick(*backend, scene, float(kWidth), 8.0f).hit());
}

TEST(Picking, HiddenInstancesDoNotShiftTheIndices) {
    Scene scene = twoShapes();
    scene.instances[0].visible = false;  // before the box in scene order: not traced
    auto backend = syncedBackend(scene);
    const Vec2 box = project(scene, scene.instances[1].objectToWorld.translation());
    const PickResult hit = pick(*backend, scene, box.x, box.y);
    EXPECT_EQ(hit.instance, 1);
    EXPECT_EQ(hit.object, 1);
    const Vec2 ball = project(scene, scene.instances[0].objectToWorld.translation());
    EXPECT_FALSE(pick(*backend, scene, ball.x, ball.y).hit())
        << "a hidden object is not drawn, so not picked";
}

TEST(Picking, FocusDistanceIsTheDepthAlongTheViewDirection) {
    Scene scene;
    scene.render = {kWidth, kHeight, 2, 1, 0};
    scene.camera.position = {0, 0, 5};
    scene.camera.lookAt = {0, 0, 0};
    scene.camera.apertureRadius = 0.2f;  // picking goes through the lens centre
    const uint32_t m = addMaterial(scene, "grey", diffuse({0.5f, 0.5f, 0.5f}));
    // A quad facing the camera (+Z) at z = -2: depth 7 at every pixel.
    addShape(scene, ObjectKind::Quad, trs({0, 0, -2}, {90, 0, 0}, {10, 1, 10}), m, "wall");
    auto backend = syncedBackend(scene);
    for (const Vec2 at : {Vec2(16.0f, 8.0f), Vec2(3.5f, 2.25f), Vec2(30.0f, 14.5f)}) {
        const PickResult hit = pick(*backend, scene, at.x, at.y);
        ASSERT_TRUE(hit.hit());
        EXPECT_NEAR(hit.focusDistance, 7.0f, 7e-4f) << at.x << ", " << at.y;
        const Ray ray = viewportRay(scene.camera, kWidth, kHeight, at.x, at.y);
        const float t = (-2.0f - ray.origin.z) / ray.direction.z;
        const float distance = t * length(ray.direction);
        EXPECT_NEAR(hit.distance, distance, 1e-4f * distance);
    }
    EXPECT_GT(pick(*backend, scene, 0.5f, 0.5f).distance, 7.5f) << "a corner ray is oblique";
}

TEST(Picking, TheCentreRayIsTheViewDirection) {
    Camera camera;
    camera.position = {3, 2, 5};
    camera.lookAt = {-1, 0.5f, 0};
    camera.verticalFovDegrees = 60.0f;
    camera.apertureRadius = 0.5f;
    const Ray ray = viewportRay(camera, 40, 20, 20.0f, 10.0f);
    const Vec3 view = normalize(camera.lookAt - camera.position);
    const Vec3 direction = normalize(ray.direction);
    EXPECT_NEAR(direction.x, view.x, 1e-5f);
    EXPECT_NEAR(direction.y, view.y, 1e-5f);
    EXPECT_NEAR(direction.z, view.z, 1e-5f);
    EXPECT_EQ(ray.origin, camera.position) << "through the lens centre";
    // Left of centre goes left (y grows down, so above centre goes up).
    const Vec3 right = normalize(cross(view, camera.up));
    EXPECT_LT(dot(viewportRay(camera, 40, 20, 5.0f, 10.0f).direction, right), 0.0f);
    EXPECT_GT(dot(viewportRay(camera, 40, 20, 20.0f, 2.0f).direction, Vec3(0, 1, 0)),
              dot(ray.direction, Vec3(0, 1, 0)));
}

}  // namespace
}  // namespace pt::editor
