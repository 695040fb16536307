// The names the Edit menu and the history list give camera, render, renderer and display edits:
// the fields that changed, not just the panel ("Undo Display" said nothing).
#include "editor/edit_labels.h"

#include <gtest/gtest.h>

#include "editor/scene_edits.h"

namespace pt::editor {
namespace {

TEST(EditLabels, NameWhatChanged) {
    Camera camera;
    Camera fov = camera;
    fov.verticalFovDegrees = 30.0f;
    EXPECT_EQ(cameraEditLabel(camera, fov), "Camera: field of view");
    Camera orbit = camera;
    orbit.position.x += 1.0f;
    orbit.focusDistance = 2.0f;
    EXPECT_EQ(cameraEditLabel(camera, orbit), "Camera: position, focus distance");
    EXPECT_EQ(cameraEditLabel(camera, camera), "Camera");

    RenderSettings render;
    RenderSettings deeper = render;
    deeper.maxDepth = 12;
    EXPECT_EQ(renderSettingsEditLabel(render, deeper), "Render settings: max depth 12");

    IntegratorToggles toggles;
    IntegratorToggles noNee = toggles;
    noNee.nextEventEstimation = false;
    EXPECT_EQ(togglesEditLabel(toggles, noNee), "Renderer: next-event estimation off");

    ViewerSettings viewer;
    ViewerSettings albedo = viewer;
    albedo.aov = int32_t(Aov::Albedo);
    albedo.display.exposureStops = 1.5f;
    EXPECT_EQ(viewerEditLabel(viewer, albedo), "Display: AOV albedo, exposure");
    ViewerSettings denoised = viewer;
    denoised.denoise = true;
    EXPECT_EQ(viewerEditLabel(viewer, denoised), "Display: denoise on");
}

// The commands carry those names (what "Undo ..." shows).
TEST(EditLabels, CommandsAreNamedByThem) {
    Document doc;
    ViewerSettings viewer = doc.viewer;
    viewer.display.exposureStops = -3.0f;
    EXPECT_EQ(setViewer(doc, viewer)->label(), "Display: exposure");
    Camera camera = doc.scene.camera;
    camera.apertureRadius = 0.1f;
    EXPECT_EQ(setCamera(doc, camera)->label(), "Camera: aperture");
}

}  // namespace
}  // namespace pt::editor
