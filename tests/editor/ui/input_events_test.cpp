// The window's input as events (editor/ui/input_events.h) and when the window draws
// (redraw_policy.h): what a slow UI frame used to lose, and an idle window that waits.
#include "editor/ui/input_events.h"

#include <gtest/gtest.h>

#include "editor/ui/gl.h"
#include "editor/ui/redraw_policy.h"

namespace pt::editor {
namespace {

// Ctrl+Z tapped within one frame: Ctrl is up again before the frame looks, but the Z press
// carried it (the frame-time key state saw a plain Z).
TEST(InputEvents, AChordKeepsTheModifiersOfItsPress) {
    InputEvents events;
    events.key(GLFW_KEY_LEFT_CONTROL, GLFW_PRESS, kModCtrl);
    events.key(GLFW_KEY_Z, GLFW_PRESS, kModCtrl);
    events.key(GLFW_KEY_Z, GLFW_RELEASE, kModCtrl);
    events.key(GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE, 0);
    EXPECT_TRUE(events.chord(GLFW_KEY_Z, kModCtrl));
    EXPECT_FALSE(events.chord(GLFW_KEY_Z, kModCtrl | kModShift)) << "Ctrl+Z is not Ctrl+Shift+Z (redo)";
    EXPECT_FALSE(events.chord(GLFW_KEY_Z, 0));
    EXPECT_TRUE(events.tapped(GLFW_KEY_Z));
    events.endFrame();
    EXPECT_FALSE(events.chord(GLFW_KEY_Z, kModCtrl)) << "a tap is the frame's only";

    // Caps Lock (0x10) and Num Lock (0x20) do not change what a chord is.
    events.key(GLFW_KEY_Z, GLFW_PRESS, kModCtrl | kModShift | 0x10 | 0x20);
    EXPECT_TRUE(events.chord(GLFW_KEY_Z, kModCtrl | kModShift));
    // A repeat is not a press.
    events.endFrame();
    events.key(GLFW_KEY_Z, GLFW_REPEAT, kModCtrl);
    EXPECT_FALSE(events.tapped(GLFW_KEY_Z));
}

// Navigation keys count as held only from a press without Ctrl or Alt: Ctrl+S, Ctrl+Q, Ctrl+D and
// Ctrl+E are shortcuts, never a camera step, whatever order the key releases come in.
TEST(InputEvents, ShortcutKeysAreNotHeldForNavigation) {
    InputEvents events;
    events.key(GLFW_KEY_LEFT_CONTROL, GLFW_PRESS, kModCtrl);
    events.key(GLFW_KEY_Q, GLFW_PRESS, kModCtrl);
    events.key(GLFW_KEY_LEFT_CONTROL, GLFW_RELEASE, 0);  // Ctrl up first: Q alone is down now
    EXPECT_FALSE(events.heldPlain(GLFW_KEY_Q));
    events.key(GLFW_KEY_Q, GLFW_RELEASE, 0);

    events.key(GLFW_KEY_W, GLFW_PRESS, kModShift);  // Shift flies faster: still navigation
    EXPECT_TRUE(events.heldPlain(GLFW_KEY_W));
    events.key(GLFW_KEY_W, GLFW_REPEAT, kModShift);
    events.endFrame();
    EXPECT_TRUE(events.heldPlain(GLFW_KEY_W)) << "held across frames";
    events.key(GLFW_KEY_W, GLFW_RELEASE, 0);
    EXPECT_FALSE(events.heldPlain(GLFW_KEY_W));
}

// Both presses of a double-click in one frame (a 200 ms frame at 5 fps): paired by their own
// times and places.
TEST(InputEvents, ADoubleClickIsPairedByItsPressesTimes) {
    InputEvents events;
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {100, 50}, 10.00);
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, {100, 50}, 10.05);
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {102, 51}, 10.15);
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, {102, 51}, 10.20);
    const std::optional<ScreenPoint> at = events.doubleClick(GLFW_MOUSE_BUTTON_LEFT);
    ASSERT_TRUE(at.has_value());
    EXPECT_EQ(at->x, 102);
    EXPECT_EQ(at->y, 51);
    EXPECT_FALSE(events.doubleClick(GLFW_MOUSE_BUTTON_RIGHT).has_value());

    // Across frames too: the first press is remembered past endFrame().
    events.endFrame();
    EXPECT_FALSE(events.doubleClick(GLFW_MOUSE_BUTTON_LEFT).has_value());
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {10, 10}, 20.0);
    events.endFrame();
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {10, 10}, 20.25);
    EXPECT_TRUE(events.doubleClick(GLFW_MOUSE_BUTTON_LEFT).has_value());
    events.endFrame();

    // Too slow, too far, or another button: two clicks.
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {10, 10}, 30.0);
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {10, 10},
                       30.0 + InputEvents::kDoubleClickSeconds + 0.01);
    EXPECT_FALSE(events.doubleClick(GLFW_MOUSE_BUTTON_LEFT).has_value()) << "too slow";
    events.endFrame();
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {10, 10}, 40.0);
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {10 + InputEvents::kDoubleClickDistance + 1, 10},
                       40.1);
    EXPECT_FALSE(events.doubleClick(GLFW_MOUSE_BUTTON_LEFT).has_value()) << "too far";
    events.endFrame();
    events.mouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, {10, 10}, 50.0);
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {10, 10}, 50.1);
    EXPECT_FALSE(events.doubleClick(GLFW_MOUSE_BUTTON_LEFT).has_value()) << "another button";

    // A triple click is one double-click, not two.
    events.endFrame();
    for (int i = 0; i < 3; ++i)
        events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {5, 5}, 60.0 + 0.1 * i);
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, {5, 5}, 60.3);
    EXPECT_TRUE(events.doubleClick(GLFW_MOUSE_BUTTON_LEFT).has_value());
}

TEST(InputEvents, EveryEventCounts) {
    InputEvents events;
    events.other();
    events.key(GLFW_KEY_A, GLFW_RELEASE, 0);
    events.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, {0, 0}, 1.0);
    EXPECT_EQ(events.count(), 3u);
    events.endFrame();
    EXPECT_EQ(events.count(), 3u) << "the count is not the frame's";
}

// A still window waits for events; anything that happens buys a few frames; a drag draws
// every frame; progress and a text field's caret draw at their own pace.
TEST(RedrawPolicy, AnIdleWindowWaitsForEvents) {
    RedrawPolicy policy;
    const FrameActivity idle;
    for (int i = 0; i < RedrawPolicy::kSettleFrames; ++i)
        EXPECT_EQ(policy.afterFrame(idle), 0.0) << "starting";
    EXPECT_EQ(policy.afterFrame(idle), RedrawPolicy::kForever);
    EXPECT_EQ(policy.afterFrame(idle), RedrawPolicy::kForever);

    FrameActivity happened;
    happened.happened = true;
    EXPECT_EQ(policy.afterFrame(happened), 0.0);
    for (int i = 1; i < RedrawPolicy::kSettleFrames; ++i) EXPECT_EQ(policy.afterFrame(idle), 0.0) << i;
    EXPECT_EQ(policy.afterFrame(idle), RedrawPolicy::kForever);

    FrameActivity moving;
    moving.moving = true;
    for (int i = 0; i < 10; ++i) EXPECT_EQ(policy.afterFrame(moving), 0.0);
    for (int i = 1; i < RedrawPolicy::kSettleFrames; ++i) policy.afterFrame(idle);

    FrameActivity progress;
    progress.progress = true;
    EXPECT_EQ(policy.afterFrame(progress), RedrawPolicy::kProgressSeconds);
    FrameActivity typing;
    typing.textInput = true;
    EXPECT_EQ(policy.afterFrame(typing), RedrawPolicy::kCaretSeconds);
}

}  // namespace
}  // namespace pt::editor
