#include "render/display/display_transform.h"

#include <cmath>

namespace pt {

const char* toneMapperName(ToneMapper op) {
    switch (op) {
    case ToneMapper::Reinhard: return "reinhard";
    case ToneMapper::AcesFitted: return "aces-fitted";
    case ToneMapper::AgX: return "agx";
    default: return "standard";
    }
}

bool parseToneMapper(const std::string& name, ToneMapper& op) {
    for (uint32_t i = 0; i < uint32_t(ToneMapper::Count); ++i) {
        if (name == toneMapperName(ToneMapper(i))) {
            op = ToneMapper(i);
            return true;
        }
    }
    return false;
}

std::vector<uint8_t> encodeDisplay8(const std::vector<float>& rgba, uint32_t width,
                                    const DisplaySettings& display) {
    const size_t pixels = rgba.size() / 4;
    std::vector<uint8_t> out(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) {
        Vec3 linear;
        for (int c = 0; c < 3; ++c) {
            const float v = rgba[i * 4 + size_t(c)];
            linear[c] = std::isfinite(v) ? v : 0.0f;
        }
        const Vec3 encoded = displayEncode(linear, display);
        const float offset =
            display.dither && width > 0 ? ditherOffset(uint32_t(i % width), uint32_t(i / width)) : 0.0f;
        for (int c = 0; c < 3; ++c) out[i * 3 + size_t(c)] = quantize8(encoded[c], offset);
    }
    return out;
}

}  // namespace pt
