#pragma once
// Input as events, each with the modifiers and time it came with. ImGui 1.86's GLFW backend
// keeps, per key, only whether it is down at the start of a frame, so when frames are slow
// (5-7 a second while a large render runs) input was lost (issue 20, defect 5):
//   - a quick tap's press and release land in one frame, and ImGui never sees the key down;
//   - Ctrl read at frame time may be up again, so a quick Ctrl+Z is a plain Z;
//   - both presses of a double-click land in one frame, or in frames whose times ImGui takes
//     for the clicks' times, and no double-click is seen.
// GLFW callbacks installed before ImGui's (which chain to them) record every press here; the
// frame reads them and endFrame() forgets them. Every event also counts, so that the frame loop
// knows whether anything happened (redraw_policy.h).
#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

struct GLFWwindow;

namespace pt::editor {

// GLFW's modifier bits (GLFW_MOD_*; checked in input_events.cpp).
constexpr int kModShift = 0x1, kModCtrl = 0x2, kModAlt = 0x4;

struct ScreenPoint {
    float x = 0, y = 0;
};

class InputEvents {
public:
    // ImGui's defaults for a double-click (io.MouseDoubleClickTime, io.MouseDoubleClickMaxDist).
    static constexpr double kDoubleClickSeconds = 0.30;
    static constexpr float kDoubleClickDistance = 6.0f;

    void key(int key, int action, int mods);
    void mouseButton(int button, int action, ScreenPoint at, double seconds);
    void other() { counted(); }  // a scroll, character, focus or resize: counted only
    // The pointer moved to `at`: a press takes the position of the last move before it (events
    // come in order), not where the pointer is when its callback runs, a frame later or more.
    void cursorMoved(ScreenPoint at) {
        counted();
        cursor_ = at;
    }
    const std::optional<ScreenPoint>& cursor() const { return cursor_; }

    // `key` pressed since the last endFrame(), with any modifiers.
    bool tapped(int key) const;
    // `key` pressed with exactly the modifiers `mods` among Shift, Ctrl and Alt (so Ctrl+Z is
    // not Ctrl+Shift+Z); other bits (Caps Lock, Num Lock) are ignored.
    bool chord(int key, int mods) const;
    // `key` is down from a press made without Ctrl or Alt: a navigation key (WASD, Q/E). Ctrl+S
    // is no step backwards, even in a frame that sees S down after Ctrl came up (which flew the
    // camera on Ctrl+Q and Ctrl+S, so that quitting asked to save a camera move).
    bool heldPlain(int key) const;
    // Where the second press of a double-click of `button` was, if one came since endFrame().
    std::optional<ScreenPoint> doubleClick(int button) const;
    // Where the first press of `button` since endFrame() was: ImGui takes a click where the
    // pointer is at frame time, by which a quick press-and-drag has left what it pressed.
    std::optional<ScreenPoint> pressed(int button) const;
    // Events of any kind so far; a change means the frame has something to show.
    uint64_t count() const { return count_; }
    // When the first event since endFrame() reached the window (its callback ran): where an
    // edit's wait for the screen starts (ScreenLatency).
    const std::optional<std::chrono::steady_clock::time_point>& firstEventTime() const { return firstEvent_; }
    void endFrame();

    struct Click {
        int button = -1;
        ScreenPoint at;
        double seconds = 0.0;
    };

private:
    struct Press {
        int key = 0, mods = 0;
    };
    std::vector<Press> presses_;
    std::vector<int> heldPlain_;  // keys down since a press without Ctrl or Alt
    std::vector<Click> doubleClicks_, clicks_;
    Click lastClick_;  // the last press of any button, which a double-click pairs with
    void counted();    // every event: the count, and the time of the frame's first
    uint64_t count_ = 0;
    std::optional<std::chrono::steady_clock::time_point> firstEvent_;
    std::optional<ScreenPoint> cursor_;  // none before the first move
};

// The window's events (the window's thread only).
InputEvents& inputEvents();
// Before ImGui_ImplGlfw_InitForOpenGL, whose callbacks chain to these.
void installInputCallbacks(GLFWwindow* window);

}  // namespace pt::editor
