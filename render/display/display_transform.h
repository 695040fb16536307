#pragma once
// The display transform until OpenColorIO arrives (color issue): exposure in stops, then the
// plain sRGB encoding of clamped linear Rec.709, quantised to 8 bits.
#include <cstdint>
#include <vector>

#include "render/math/vec.h"

namespace pt {

PT_HD float linearToSrgb(float c) {
    c = clampf(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * powf(c, 1.0f / 2.4f) - 0.055f;
}

// RGBA float (linear) -> RGB 8-bit (sRGB-encoded), same pixel order.
std::vector<uint8_t> encodeSrgb8(const std::vector<float>& rgba, float exposureStops = 0.0f);

}  // namespace pt
