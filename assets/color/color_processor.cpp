// DisplayProcessor, the parts every build has: the built-in operators, exposure, dithering,
// quantisation. The OpenColorIO constructor is in color_processor_ocio.cpp.
#include "assets/color/color_processor.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace pt {

namespace {

std::string formatNumber(const char* format, float value) {
    char text[32];
    std::snprintf(text, sizeof(text), format, double(value));
    return text;
}

}  // namespace

DisplayProcessor::DisplayProcessor(const DisplaySettings& builtin)
    : builtin_(builtin), exposureStops_(builtin.exposureStops) {}

void DisplayProcessor::applyInPlace(std::vector<float>& rgba) const {
    const size_t pixels = rgba.size() / 4;
    if (ocio_) {
        const float scale = std::exp2(exposureStops_);
        for (size_t i = 0; i < pixels; ++i) {
            for (size_t c = 0; c < 3; ++c) {
                float& v = rgba[i * 4 + c];
                v = std::isfinite(v) ? v * scale : 0.0f;
            }
        }
        ocio_(rgba.data(), pixels);  // RGB only: alpha stays
        return;
    }
    displayEncodeInPlace(rgba, builtin_);
}

std::vector<uint8_t> DisplayProcessor::encode8(const std::vector<float>& rgba, uint32_t width,
                                               bool dither) const {
    std::vector<float> display = rgba;
    applyInPlace(display);
    return quantizeDisplay8(display, width, dither);
}

std::string DisplayProcessor::describe() const {
    std::string text;
    if (ocio_) {
        text = "OCIO " + std::filesystem::path(configPath_).filename().string() + ": " + view_.display +
               " / " + view_.view;
        if (!view_.look.empty()) text += " / look " + view_.look;
    } else {
        text = std::string("built-in: ") + toneMapperName(builtin_.toneMapper);
        if (builtin_.toneMapper == ToneMapper::Reinhard)
            text += formatNumber(" (white %g)", builtin_.whitePoint);
    }
    if (exposureStops_ != 0.0f) text += formatNumber(", exposure %+g stops", exposureStops_);
    return text;
}

ImageMetadata displayMetadata(const DisplayProcessor& display, bool dither) {
    ImageMetadata metadata;
    if (display.usesOcio()) metadata.emplace_back("pt:ocio_config", display.configPath());
    metadata.emplace_back("pt:view", display.describe());
    metadata.emplace_back("pt:dither", dither ? "on" : "off");
    return metadata;
}

}  // namespace pt
