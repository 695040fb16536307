// The viewport's selection outline (editor/selection_box.h): the selected object's world box
// projected through the camera, 12 edges where it is in front, none behind.
#include "editor/selection_box.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/scene_builder.h"

namespace pt::editor {
namespace {

Scene twoBoxes() {
    Scene scene;
    scene.render = {100, 100, 1, 1, 0};
    scene.camera.position = {0, 0, 5};
    scene.camera.lookAt = {0, 0, 0};
    const uint32_t m = test::addMaterial(scene, "grey", test::diffuse({0.5f, 0.5f, 0.5f}));
    test::addShape(scene, ObjectKind::Box, test::trs({0, 0, 0}, {0, 0, 0}, {0.5f, 0.5f, 0.5f}), m, "centre");
    test::addShape(scene, ObjectKind::Box, test::trs({0, 0, 9}, {0, 0, 0}, {0.5f, 0.5f, 0.5f}), m, "behind");
    return scene;
}

// The outline of a selection, as the window draws it.
std::vector<ImageSegment> outline(const Scene& scene, int32_t object, int32_t instance) {
    const std::optional<WorldBox> box = selectionBounds(scene, object, instance);
    return box ? boxInImage(*box, scene.camera, 100, 100) : std::vector<ImageSegment>{};
}

TEST(SelectionBox, TheBoxInFrontProjectsAroundItsCentre) {
    const Scene scene = twoBoxes();
    const std::vector<ImageSegment> edges = outline(scene, 0, -1);
    ASSERT_EQ(edges.size(), 12u);
    float minX = 1e9f, maxX = -1e9f, minY = 1e9f, maxY = -1e9f;
    for (const ImageSegment& e : edges) {
        for (const Vec2 p : {e.a, e.b}) {
            minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
            minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
        }
    }
    // Symmetric about the image centre, inside the image (a box of side 1 at 4.5-5.5 units, 45 degrees).
    EXPECT_NEAR(minX + maxX, 100.0f, 1e-3f);
    EXPECT_NEAR(minY + maxY, 100.0f, 1e-3f);
    EXPECT_GT(minX, 0.0f);
    EXPECT_LT(maxX, 100.0f);
    // Its near face (z = 0.5, 4.5 from the camera) spans 1 / (2 * 4.5 * tan(22.5 deg)) of the width.
    EXPECT_NEAR(maxX - minX, 100.0f / (2.0f * 4.5f * std::tan(22.5f * 3.14159265f / 180.0f)), 1e-2f);
}

TEST(SelectionBox, NothingBehindTheCameraOrUnselected) {
    const Scene scene = twoBoxes();
    EXPECT_TRUE(outline(scene, 1, -1).empty()) << "the box behind the camera";
    EXPECT_EQ(outline(scene, -1, 0).size(), 12u) << "an instance by index";
    EXPECT_FALSE(selectionBounds(scene, -1, -1).has_value());
    EXPECT_FALSE(selectionBounds(scene, 7, -1).has_value());
}

}  // namespace
}  // namespace pt::editor
