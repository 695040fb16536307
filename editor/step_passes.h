#pragma once
// How many passes (samples a pixel) the render thread adds in one step when the viewer's
// "samples per frame" is automatic. One pass right after an edit (the accumulation is empty),
// so the first frame of the edit comes as soon as one sample is done; after that as many as
// fit in about a display frame, so the image clears faster without an edit waiting longer than
// that for the step in flight. A step of several passes is faster per sample on the GPU: the
// CUDA backend traces them as one wave, which pays each launch's tail once (H100, 1080p, bench:
// 4 samples a call against 1, the Cornell box 321 vs 273 spp/s, Balloon 769 vs 418).
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pt::editor {

constexpr double kAutoStepSeconds = 1.0 / 60.0;
constexpr uint32_t kMaxAutoPasses = 16;

// `secondsPerPass`: as the last step measured it (0: not measured yet); `samplesSoFar`: the
// accumulation's samples a pixel.
inline uint32_t autoPassesPerStep(double secondsPerPass, uint32_t samplesSoFar) {
    if (samplesSoFar == 0 || !(secondsPerPass > 0.0)) return 1;
    const double fit = std::floor(kAutoStepSeconds / secondsPerPass);
    return uint32_t(std::clamp(fit, 1.0, double(kMaxAutoPasses)));
}

}  // namespace pt::editor
