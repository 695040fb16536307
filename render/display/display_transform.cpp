#include "render/display/display_transform.h"

#include <cmath>

namespace pt {

const char* toneMapperName(ToneMapper op) {
    switch (op) {
    case ToneMapper::Reinhard: return "reinhard";
    case ToneMapper::AcesFitted: return "aces-fitted";
    default: return "standard";
    }
}

std::vector<uint8_t> encodeDisplay8(const std::vector<float>& rgba, const DisplaySettings& display) {
    const size_t pixels = rgba.size() / 4;
    std::vector<uint8_t> out(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) {
        Vec3 linear;
        for (int c = 0; c < 3; ++c) {
            const float v = rgba[i * 4 + size_t(c)];
            linear[c] = std::isfinite(v) ? v : 0.0f;
        }
        const Vec3 encoded = displayEncode(linear, display);
        for (int c = 0; c < 3; ++c) out[i * 3 + size_t(c)] = uint8_t(std::lround(encoded[c] * 255.0f));
    }
    return out;
}

}  // namespace pt
