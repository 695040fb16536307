// The panels' column (editor/ui/panel_layout.h): its remembered width, read back as written,
// scaled for a high-DPI screen, kept within the window, and defaults for a damaged file.
#include "editor/ui/panel_layout.h"

#include <gtest/gtest.h>

namespace pt::editor {
namespace {

TEST(PanelLayout, TheWidthRoundTripsAtEveryScale) {
    PanelLayout layout = PanelLayout::parse("", 1.0f);
    EXPECT_EQ(layout.width, PanelLayout::kDefaultWidth);
    layout.width = 520.0f;
    EXPECT_EQ(PanelLayout::parse(layout.serialize(), 1.0f).width, 520.0f);
    // Saved at scale 2 (1040 px), opened at 1: the same column in points.
    PanelLayout hiDpi = PanelLayout::parse("panel_width 520\n", 2.0f);
    EXPECT_EQ(hiDpi.width, 1040.0f);
    EXPECT_EQ(hiDpi.serialize(), "panel_width 520\nstats_overlay 0\n");
}

TEST(PanelLayout, TheStatsOverlayIsRemembered) {
    EXPECT_FALSE(PanelLayout::parse("panel_width 520\n", 1.0f).statsOverlay) << "off unless asked";
    PanelLayout layout = PanelLayout::parse("", 1.0f);
    layout.statsOverlay = true;
    const PanelLayout read = PanelLayout::parse(layout.serialize(), 1.0f);
    EXPECT_TRUE(read.statsOverlay);
    EXPECT_EQ(read.width, layout.width);
    EXPECT_FALSE(PanelLayout::parse("stats_overlay 7\n", 1.0f).statsOverlay);
}

TEST(PanelLayout, DamagedOrExtremeFilesGiveTheDefault) {
    for (const char* text :
         {"panel_width nan\n", "panel_width 10\n", "panel_width 1e9\n", "garbage", "panel_width"}) {
        EXPECT_EQ(PanelLayout::parse(text, 1.0f).width, PanelLayout::kDefaultWidth) << text;
    }
}

TEST(PanelLayout, TheColumnLeavesTheViewportRoom) {
    PanelLayout layout;
    layout.width = 900.0f;
    EXPECT_EQ(layout.clampedWidth(1000.0f), 1000.0f - PanelLayout::kMinViewport);
    layout.width = 100.0f;
    EXPECT_EQ(layout.clampedWidth(1000.0f), PanelLayout::kMinWidth);
    layout.width = 400.0f;
    EXPECT_EQ(layout.clampedWidth(1000.0f), 400.0f);
}

}  // namespace
}  // namespace pt::editor
