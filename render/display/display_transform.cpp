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

void displayEncodeInPlace(std::vector<float>& rgba, const DisplaySettings& display) {
    for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
        Vec3 linear;
        for (int c = 0; c < 3; ++c) {
            const float v = rgba[i + size_t(c)];
            linear[c] = std::isfinite(v) ? v : 0.0f;
        }
        const Vec3 encoded = displayEncode(linear, display);
        for (int c = 0; c < 3; ++c) rgba[i + size_t(c)] = encoded[c];
    }
}

std::vector<uint8_t> quantizeDisplay8(const std::vector<float>& displayRgba, uint32_t width, bool dither) {
    const size_t pixels = displayRgba.size() / 4;
    std::vector<uint8_t> out(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) {
        const float offset =
            dither && width > 0 ? ditherOffset(uint32_t(i % width), uint32_t(i / width)) : 0.0f;
        for (size_t c = 0; c < 3; ++c) {
            const float v = displayRgba[i * 4 + c];
            out[i * 3 + c] = quantize8(std::isfinite(v) ? v : 0.0f, offset);
        }
    }
    return out;
}

std::vector<uint8_t> encodeDisplay8(const std::vector<float>& rgba, uint32_t width,
                                    const DisplaySettings& display) {
    std::vector<float> encoded = rgba;
    displayEncodeInPlace(encoded, display);
    return quantizeDisplay8(encoded, width, display.dither);
}

}  // namespace pt
