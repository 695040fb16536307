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

TEST(PanelLayout, FloatingPanelsAreRemembered) {
    PanelLayout layout = PanelLayout::parse("", 1.0f);
    EXPECT_TRUE(layout.floating.empty());
    layout.setFloating("Render settings", true);
    layout.setFloating("Stats", true);
    layout.setFloating("Stats", true);  // once only
    const PanelLayout read = PanelLayout::parse(layout.serialize(), 1.0f);
    EXPECT_EQ(read.floating, (std::vector<std::string>{"Render settings", "Stats"}));
    EXPECT_TRUE(read.floats("Render settings"));
    EXPECT_FALSE(read.floats("Outliner"));
    layout.setFloating("Render settings", false);
    EXPECT_EQ(layout.floating, std::vector<std::string>{"Stats"});
    EXPECT_TRUE(PanelLayout::parse("floating Nonsense\nfloating\n", 1.0f).floating.empty())
        << "names that are no panel are dropped";
    EXPECT_EQ(PanelLayout::parse("floating Stats\npanel_width 500\n", 1.0f).width, 500.0f);
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
