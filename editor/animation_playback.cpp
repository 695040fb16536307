#include "editor/animation_playback.h"

#include <cmath>

namespace pt::editor {

float AnimationPlayback::advance(float time, float duration, double elapsed) {
    if (!playing_ || !(duration > 0.0f)) return time;
    const double next = double(time) + elapsed * double(speed);
    if (loop) {
        const double wrapped = std::fmod(next, double(duration));
        return float(wrapped < 0.0 ? wrapped + double(duration) : wrapped);
    }
    if (next >= double(duration) || next <= 0.0) {
        playing_ = false;
        return next <= 0.0 ? 0.0f : duration;
    }
    return float(next);
}

}  // namespace pt::editor
