// The viewport's transform gizmo (editor/transform_gizmo.h): handles where the camera shows them,
// drags that follow the cursor in world units, snapping, rotation round and round, scale along
// the object's own axes, and transforms that stay what scene JSON keeps.
#include "editor/transform_gizmo.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pt::editor {
namespace {

constexpr float kHandle = 50.0f;  // image pixels
constexpr float kSlop = 6.0f;

// 200 x 200 pixels, 45 degrees, from +Z 5 units out: one pixel at the origin is
// 2 * 5 * tan(22.5 degrees) / 200 world units.
GizmoView frontView() {
    GizmoView view;
    view.camera.position = {0, 0, 5};
    view.camera.lookAt = {0, 0, 0};
    view.camera.verticalFovDegrees = 45.0f;
    view.width = view.height = 200;
    return view;
}

const float kWorldPerPixel = 2.0f * 5.0f * std::tan(22.5f * kPi / 180.0f) / 200.0f;

Gizmo place(const Affine3& at, GizmoMode mode, GizmoSpace space = GizmoSpace::World) {
    const std::optional<Gizmo> g = placeGizmo(at, mode, space, frontView(), kHandle);
    EXPECT_TRUE(g.has_value());
    return g.value_or(Gizmo{});
}

void expectNear(const Affine3& a, const Affine3& b, float tolerance) {
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(a.at(r, c), b.at(r, c), tolerance) << "entry " << r << "," << c;
    }
}

TEST(TransformGizmo, HandlesLieWhereTheCameraShowsThemAndKeepTheirSizeOnScreen) {
    const Gizmo g = place(Affine3{}, GizmoMode::Translate);
    EXPECT_NEAR(g.size, kHandle * kWorldPerPixel, 1e-5f);
    const GizmoView view = frontView();
    // X to the right of the image centre, Y up (image y down); Z points at the camera: left out.
    EXPECT_EQ(gizmoHandleAt(g, view, {100 + 40, 100}, kSlop), 0);
    EXPECT_EQ(gizmoHandleAt(g, view, {100, 100 - 40}, kSlop), 1);
    EXPECT_EQ(gizmoHandleAt(g, view, {100, 100}, kSlop), kCentreHandle);
    EXPECT_EQ(gizmoHandleAt(g, view, {100 + 40, 100 + 40}, kSlop), kNoHandle);
    EXPECT_EQ(gizmoHandleAt(g, view, {100 + kHandle + 2 * kSlop, 100}, kSlop), kNoHandle) << "past the tip";
    for (const GizmoShape& s : gizmoShapes(g, view)) EXPECT_NE(s.handle, 2) << "Z is seen end-on";

    // Ten times as far: ten times as big in the world, as big on screen.
    const std::optional<Gizmo> far =
        placeGizmo(translationTransform({0, 0, -45}), GizmoMode::Translate, GizmoSpace::World, view, kHandle);
    ASSERT_TRUE(far.has_value());
    EXPECT_NEAR(far->size, 10.0f * g.size, 1e-4f);
    EXPECT_FALSE(
        placeGizmo(translationTransform({0, 0, 9}), GizmoMode::Translate, GizmoSpace::World, view, kHandle))
        << "behind the camera";
}

TEST(TransformGizmo, AnAxisDragFollowsTheCursorInWorldUnitsAndSnapsItsAmount) {
    const GizmoView view = frontView();
    const Gizmo g = place(Affine3{}, GizmoMode::Translate);
    GizmoDrag drag(g, 0, view, {120, 100});
    GizmoEdit edit = drag.moveTo({150, 130}, nullptr);  // 30 px right (and 30 down, across the axis)
    EXPECT_NEAR(edit.translate.x, 30.0f * kWorldPerPixel, 1e-4f);
    EXPECT_NEAR(edit.translate.y, 0.0f, 1e-6f);
    EXPECT_NEAR(edit.translate.z, 0.0f, 1e-6f);

    const GizmoSnap snap;  // 0.1 units
    edit = drag.moveTo({150, 100}, &snap);
    const float steps = edit.translate.x / snap.translate;
    EXPECT_NEAR(steps, std::round(steps), 1e-4f);
    EXPECT_NEAR(edit.translate.x, std::round(30.0f * kWorldPerPixel / 0.1f) * 0.1f, 1e-5f);

    // The centre moves in the plane facing the camera.
    GizmoDrag centre(g, kCentreHandle, view, {100, 100});
    edit = centre.moveTo({110, 80}, nullptr);
    EXPECT_NEAR(edit.translate.x, 10.0f * kWorldPerPixel, 1e-4f);
    EXPECT_NEAR(edit.translate.y, 20.0f * kWorldPerPixel, 1e-4f);
    EXPECT_NEAR(edit.translate.z, 0.0f, 1e-5f);
}

TEST(TransformGizmo, RotationFollowsTheCursorRoundThePivotPastHalfATurn) {
    const GizmoView view = frontView();
    const Gizmo g = place(Affine3{}, GizmoMode::Rotate);
    // Z's ring faces the camera: a circle of kHandle pixels round the image centre.
    EXPECT_EQ(gizmoHandleAt(g, view, {100 + kHandle, 100}, kSlop), 2);
    GizmoDrag drag(g, 2, view, {100 + kHandle, 100});
    // A quarter turn counter-clockwise on screen is +90 degrees about +Z (it points at us).
    GizmoEdit edit = drag.moveTo({100, 100 - kHandle}, nullptr);
    EXPECT_NEAR(edit.rotationRadians, 0.5f * kPi, 1e-4f);
    const Affine3 turned = applyGizmoEdit(Affine3{}, edit);
    EXPECT_NEAR(turned.transformVector({1, 0, 0}).y, 1.0f, 1e-5f) << "X turns onto Y";
    // On round, in quarter steps: three quarters, then a whole turn and a bit, not folded back.
    drag.moveTo({100 - kHandle, 100}, nullptr);
    edit = drag.moveTo({100, 100 + kHandle}, nullptr);
    EXPECT_NEAR(edit.rotationRadians, 1.5f * kPi, 1e-4f);
    drag.moveTo({100 + kHandle, 100 + 1}, nullptr);
    const GizmoSnap snap;  // 15 degrees
    edit = drag.moveTo({100 + kHandle, 100 - 10}, &snap);
    EXPECT_NEAR(edit.rotationRadians * 180.0f / kPi, 375.0f, 1e-3f)
        << "atan(10/50) = 11.3 degrees snaps to 15";
}

TEST(TransformGizmo, ARotatedObjectKeepsEulerAnglesThatAgreeWithItsMatrix) {
    ObjectTransform start;
    start.translate = {1, 2, 3};
    start.rotateDegrees = {10, 20, 30};
    start.scale = {1, 2, 3};
    for (const Vec3 axis : {Vec3(0, 1, 0), Vec3(1, 0, 0), normalize(Vec3(1, 1, 1))}) {
        GizmoEdit edit;
        edit.rotationAxis = axis;
        edit.rotationRadians = 0.7f;
        const ObjectTransform after = applyGizmoEdit(start, edit);
        EXPECT_FALSE(after.useMatrix);
        EXPECT_EQ(after.translate, start.translate) << "turns about its own origin";
        EXPECT_EQ(after.scale, start.scale);
        expectNear(after.toAffine(), applyGizmoEdit(start.toAffine(), edit), 1e-4f);
        for (int i = 0; i < 3; ++i)
            EXPECT_LT(std::fabs(after.rotateDegrees[i] - start.rotateDegrees[i]), 180.0f);
    }
    // A small turn moves the angles a little (the nearest of the equivalent Euler triples).
    GizmoEdit small;
    small.rotationAxis = {0, 0, 1};
    small.rotationRadians = 0.01f;
    const ObjectTransform nudged = applyGizmoEdit(start, small);
    EXPECT_LT(length(nudged.rotateDegrees - start.rotateDegrees), 1.5f);
    // Through gimbal lock (Y at 90 degrees) the matrix still agrees.
    ObjectTransform locked;
    locked.rotateDegrees = {25, 80, 0};
    GizmoEdit toLock;
    toLock.rotationAxis = {0, 1, 0};
    toLock.rotationRadians = 10.0f * kPi / 180.0f;
    expectNear(applyGizmoEdit(locked, toLock).toAffine(), applyGizmoEdit(locked.toAffine(), toLock), 1e-4f);
}

TEST(TransformGizmo, ScaleStretchesAlongTheObjectsOwnAxesEvenInWorldSpace) {
    const GizmoView view = frontView();
    ObjectTransform start;
    start.rotateDegrees = {0, 0, 90};  // its X points along world Y
    const Gizmo g = place(start.toAffine(), GizmoMode::Scale, GizmoSpace::World);
    EXPECT_NEAR(g.axes[0].y, 1.0f, 1e-5f) << "scale handles follow the object";
    // Press halfway up its X handle (image up), drag to twice as far from the pivot.
    GizmoDrag drag(g, 0, view, {100, 100 - 25});
    const GizmoEdit edit = drag.moveTo({100, 100 - 50}, nullptr);
    EXPECT_NEAR(edit.scale.x, 2.0f, 1e-3f);
    EXPECT_EQ(edit.scale.y, 1.0f);
    const ObjectTransform after = applyGizmoEdit(start, edit);
    EXPECT_NEAR(after.scale.x, 2.0f, 1e-3f);
    EXPECT_EQ(after.rotateDegrees, start.rotateDegrees);
    EXPECT_NEAR(after.toAffine().transformVector({1, 0, 0}).y, 2.0f, 1e-3f);

    // From the centre: uniform, by the cursor's distance from the pivot; never through zero.
    GizmoDrag uniform(g, kCentreHandle, view, {110, 100});
    EXPECT_NEAR(uniform.moveTo({100, 130}, nullptr).scale.z, 3.0f, 1e-4f);
    EXPECT_GT(uniform.moveTo({100, 100}, nullptr).scale.x, 0.0f);
    GizmoSnap snap;
    snap.scale = 0.25f;
    EXPECT_NEAR(uniform.moveTo({100, 124}, &snap).scale.y, 2.5f, 1e-5f) << "2.4 snaps to 2.5";
}

TEST(TransformGizmo, LocalAxesFollowTheObjectAndAMatrixStaysAMatrix) {
    ObjectTransform start;
    start.useMatrix = true;
    const Affine3 m =
        translationTransform({0.5f, 0, 0}) * rotationTransform({0, 0, std::sin(0.3f), std::cos(0.3f)});
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) start.matrix[4 * c + r] = m.at(r, c);
    }
    const Gizmo local = place(start.toAffine(), GizmoMode::Translate, GizmoSpace::Local);
    EXPECT_NEAR(local.axes[0].x, std::cos(0.6f), 1e-5f);
    EXPECT_NEAR(local.axes[0].y, std::sin(0.6f), 1e-5f);
    const Gizmo world = place(start.toAffine(), GizmoMode::Translate, GizmoSpace::World);
    EXPECT_EQ(world.axes[0], Vec3(1, 0, 0));
    EXPECT_NEAR(world.pivot.x, 0.5f, 1e-6f);

    GizmoEdit edit;
    edit.translate = {0, 1, 0};
    edit.rotationAxis = {1, 0, 0};
    edit.rotationRadians = 0.4f;
    edit.scale = {1, 3, 1};
    const ObjectTransform after = applyGizmoEdit(start, edit);
    EXPECT_TRUE(after.useMatrix);
    expectNear(after.toAffine(), applyGizmoEdit(start.toAffine(), edit), 1e-6f);
    EXPECT_NEAR(after.toAffine().translation().y, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace pt::editor
