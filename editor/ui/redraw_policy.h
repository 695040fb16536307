#pragma once
// When the window draws. It used to draw without pause: 1.7 cores (the main thread 86%, the GL
// driver's threads the rest) to show a still image, and while rendering it starved the CPU
// backend's threads (issue 20, defect 6). Now the frame loop waits for an event (input, or the
// render thread's news: RenderWorker's onUpdate posts one) unless this says to draw on:
//   - a few frames after anything happened, for ImGui to show its effect (a popup opens the
//     frame after its click; hover and active states follow the mouse by a frame);
//   - every frame while the user drags or flies the camera (no event need come while a key
//     is held);
//   - at a progress bar's pace while something runs that sends no events (a scene load);
//   - at a caret's pace while a text field has the keyboard.
#include <limits>

namespace pt::editor {

struct FrameActivity {
    bool happened = false;   // input events, a new render frame, a dropped file, a new title
    bool moving = false;     // a camera drag or fly under way, or a mouse button held
    bool progress = false;   // a load or sync under way
    bool textInput = false;  // a text field has the keyboard
};

class RedrawPolicy {
public:
    static constexpr int kSettleFrames = 3;
    static constexpr double kProgressSeconds = 0.1;
    static constexpr double kCaretSeconds = 0.5;
    static constexpr double kForever = std::numeric_limits<double>::infinity();

    // After a frame: the longest the loop may wait for an event before drawing the next
    // (0: draw at once; kForever: only when an event comes).
    double afterFrame(const FrameActivity& frame) {
        if (frame.happened || frame.moving) settle_ = kSettleFrames;
        if (settle_ > 0) {
            --settle_;
            return 0.0;
        }
        if (frame.progress) return kProgressSeconds;
        if (frame.textInput) return kCaretSeconds;
        return kForever;
    }

private:
    int settle_ = kSettleFrames;  // the first frames draw on
};

}  // namespace pt::editor
