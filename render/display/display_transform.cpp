#include "render/display/display_transform.h"

#include <cmath>

namespace pt {

std::vector<uint8_t> encodeSrgb8(const std::vector<float>& rgba, float exposureStops) {
    const float scale = std::exp2(exposureStops);
    const size_t pixels = rgba.size() / 4;
    std::vector<uint8_t> out(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) {
            const float v = rgba[i * 4 + size_t(c)] * scale;
            out[i * 3 + size_t(c)] = uint8_t(std::lround(linearToSrgb(std::isfinite(v) ? v : 0.0f) * 255.0f));
        }
    }
    return out;
}

}  // namespace pt
