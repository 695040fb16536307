#include "editor/viewport_resolution.h"

#include <algorithm>
#include <cmath>

namespace pt::editor {

RenderSize ViewportResolution::target(float viewportWidth, float viewportHeight, float scale,
                                      bool navigating) {
    const float factor = std::clamp(scale, 0.05f, 1.0f) / (navigating ? kNavigationDivider : 1.0f);
    const auto side = [factor](float pixels) {
        return std::max(kMinSide, uint32_t(std::lround(std::max(pixels, 0.0f) * factor)));
    };
    return {side(viewportWidth), side(viewportHeight)};
}

std::optional<RenderSize> ViewportResolution::update(float viewportWidth, float viewportHeight, float scale,
                                                     bool navigating, RenderSize current, double now) {
    const RenderSize wanted = target(viewportWidth, viewportHeight, scale, navigating);
    const bool switched = navigating != navigating_ || !started_;
    navigating_ = navigating;
    started_ = true;
    if (wanted == current) {
        pending_.reset();
        return std::nullopt;
    }
    if (switched) {  // the first frame, or navigation starting or ending: at once
        pending_.reset();
        return wanted;
    }
    if (pending_ != wanted) {
        pending_ = wanted;
        pendingSince_ = now;
    }
    if (now - pendingSince_ < kSettleSeconds) return std::nullopt;
    pending_.reset();
    return wanted;
}

}  // namespace pt::editor
