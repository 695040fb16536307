// The render size that follows the viewport (editor/viewport_resolution.h): the viewport's
// pixels at the viewer's scale, a quarter a side while navigating, applied at once when the
// navigation starts or ends, after the size held still when the window is resized.
#include "editor/viewport_resolution.h"

#include <gtest/gtest.h>

namespace pt::editor {
namespace {

TEST(ViewportResolution, TheTargetIsTheViewportAtItsScale) {
    EXPECT_EQ(ViewportResolution::target(640, 480, 1.0f, false), (RenderSize{640, 480}));
    EXPECT_EQ(ViewportResolution::target(640, 480, 0.5f, false), (RenderSize{320, 240}));
    EXPECT_EQ(ViewportResolution::target(640, 480, 1.0f, true), (RenderSize{160, 120}));
    EXPECT_EQ(ViewportResolution::target(641, 479, 0.25f, true), (RenderSize{40, 30}));
    EXPECT_EQ(ViewportResolution::target(10, 0, 1.0f, true),
              (RenderSize{ViewportResolution::kMinSide, ViewportResolution::kMinSide}));
}

TEST(ViewportResolution, ResizesSettleAndNavigationSwitchesAtOnce) {
    ViewportResolution r;
    const RenderSize file{512, 512};
    // The first frame applies the viewport's size at once.
    ASSERT_EQ(r.update(640, 480, 1.0f, false, file, 0.0), (RenderSize{640, 480}));
    RenderSize current{640, 480};
    EXPECT_FALSE(r.update(640, 480, 1.0f, false, current, 0.1).has_value());
    EXPECT_FALSE(r.settling());

    // A window edge dragged: nothing until the size has held still for kSettleSeconds.
    EXPECT_FALSE(r.update(700, 480, 1.0f, false, current, 1.0).has_value());
    EXPECT_TRUE(r.settling());
    EXPECT_FALSE(r.update(760, 480, 1.0f, false, current, 1.15).has_value()) << "still moving";
    EXPECT_FALSE(r.update(760, 480, 1.0f, false, current, 1.3).has_value()) << "held 0.15 s";
    ASSERT_EQ(r.update(760, 480, 1.0f, false, current, 1.36), (RenderSize{760, 480}));
    current = {760, 480};
    EXPECT_FALSE(r.settling());

    // An orbit: a quarter a side from its first step, the full size again as soon as it ends.
    ASSERT_EQ(r.update(760, 480, 1.0f, true, current, 2.0), (RenderSize{190, 120}));
    current = {190, 120};
    EXPECT_FALSE(r.update(760, 480, 1.0f, true, current, 2.01).has_value());
    ASSERT_EQ(r.update(760, 480, 1.0f, false, current, 2.5), (RenderSize{760, 480}));
    current = {760, 480};

    // Stopped (the viewport no longer followed), the next update applies at once again.
    r.stop();
    EXPECT_FALSE(r.following());
    ASSERT_EQ(r.update(760, 480, 0.5f, false, RenderSize{512, 512}, 3.0), (RenderSize{380, 240}));
    EXPECT_TRUE(r.following());
}

}  // namespace
}  // namespace pt::editor
