#pragma once
// The render size that follows the viewport (issue 20, item 10): the viewport's framebuffer
// pixels times the viewer's resolution scale, and a quarter of that a side while the camera
// moves, so that each step of an orbit or a fly shows its first frame at a sixteenth of the
// pixels (Blender's viewport coarsens the same way while navigating). A window being resized
// applies once its size has held still for kSettleSeconds, so dragging an edge does not restart
// the accumulation at every pixel; starting or ending navigation applies at once.
#include <cstdint>
#include <optional>

namespace pt::editor {

struct RenderSize {
    uint32_t width = 0, height = 0;
    bool operator==(const RenderSize& o) const { return width == o.width && height == o.height; }
    bool operator!=(const RenderSize& o) const { return !(*this == o); }
};

class ViewportResolution {
public:
    static constexpr double kSettleSeconds = 0.2;
    static constexpr float kNavigationDivider = 4.0f;
    static constexpr uint32_t kMinSide = 8;

    // The size to render at from now on, or none to keep `current`. `viewport*`: framebuffer
    // pixels; `now`: seconds on any steady clock.
    std::optional<RenderSize> update(float viewportWidth, float viewportHeight, float scale, bool navigating,
                                     RenderSize current, double now);
    // A size is waiting to settle: the window must draw again within kSettleSeconds to apply it.
    bool settling() const { return pending_.has_value(); }
    // Whether update() has run since the start or the last stop(): the size is the viewport's.
    bool following() const { return started_; }
    void stop() {  // no longer followed; the next update() applies at once
        started_ = false;
        pending_.reset();
    }

    static RenderSize target(float viewportWidth, float viewportHeight, float scale, bool navigating);

private:
    std::optional<RenderSize> pending_;
    double pendingSince_ = 0.0;
    bool navigating_ = false;
    bool started_ = false;
};

}  // namespace pt::editor
