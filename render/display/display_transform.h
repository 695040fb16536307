#pragma once
// The built-in display transforms, for users without an OpenColorIO config (the OCIO path is
// assets/color_processor.h): exposure in stops, one of the built-in tone mappers, then the
// sRGB encoding, quantised to 8 bits with an optional dither (render/display/dither.h). The
// editor's display shader implements the same formulas in GLSL; keep them equal.
#include <cstdint>
#include <string>
#include <vector>

#include "render/display/agx.h"
#include "render/display/dither.h"
#include "render/math/vec.h"

namespace pt {

enum class ToneMapper : uint32_t {
    Clamp = 0,       // "Standard": linear clamped to [0, 1], the plain sRGB encoding
    Reinhard = 1,    // extended Reinhard on luminance, white point `whitePoint` (Reinhard 2002, eq. 4)
    AcesFitted = 2,  // Stephen Hill's fit of the ACES RRT + sRGB ODT (BakingLab, MIT)
    AgX = 3,         // AgX-style neutral filmic curve (render/display/agx.h)
    Count = 4,
};
const char* toneMapperName(ToneMapper op);  // "standard", "reinhard", "aces-fitted", "agx"
// The inverse of toneMapperName; false (and `op` untouched) for any other name.
bool parseToneMapper(const std::string& name, ToneMapper& op);

// What turns the linear accumulation into display pixels. Changing it never restarts
// accumulation (SceneChanges::Display).
struct DisplaySettings {
    float exposureStops = 0.0f;
    ToneMapper toneMapper = ToneMapper::Clamp;
    float whitePoint = 4.0f;  // Reinhard: linear luminance that maps to display white
    bool dither = true;       // triangular +-1 LSB dither before 8-bit quantisation (file export)
};

PT_HD float linearToSrgb(float c) {
    c = clampf(c, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * powf(c, 1.0f / 2.4f) - 0.055f;
}

PT_HD Vec3 reinhardExtended(Vec3 c, float whitePoint) {
    const float y = luminance(c);
    if (!(y > 0.0f)) return Vec3(0.0f);
    const float w2 = whitePoint * whitePoint;
    const float mapped = y * (1.0f + y / w2) / (1.0f + y);
    return c * (mapped / y);
}

PT_HD Vec3 acesFitted(Vec3 c) {
    // sRGB -> ACES AP1-ish input matrix, the RRT+ODT rational fit, and back (Hill's constants).
    const Vec3 a(0.59719f * c.x + 0.35458f * c.y + 0.04823f * c.z,
                 0.07600f * c.x + 0.90834f * c.y + 0.01566f * c.z,
                 0.02840f * c.x + 0.13383f * c.y + 0.83777f * c.z);
    Vec3 f;
    for (int i = 0; i < 3; ++i) {
        const float v = a[i];
        f[i] = (v * (v + 0.0245786f) - 0.000090537f) / (v * (0.983729f * v + 0.4329510f) + 0.238081f);
    }
    return Vec3(1.60475f * f.x - 0.53108f * f.y - 0.07367f * f.z,
                -0.10208f * f.x + 1.10813f * f.y - 0.00605f * f.z,
                -0.00327f * f.x - 0.07276f * f.y + 1.07602f * f.z);
}

// Linear scene radiance -> display-referred sRGB in [0, 1] (before quantisation).
PT_HD Vec3 displayEncode(Vec3 linear, const DisplaySettings& d) {
    Vec3 c = linear * exp2f(d.exposureStops);
    switch (d.toneMapper) {
        case ToneMapper::Reinhard: c = reinhardExtended(c, d.whitePoint); break;
        case ToneMapper::AcesFitted: c = acesFitted(c); break;
        case ToneMapper::AgX: c = agxToneMap(c); break;
        default: break;
    }
    return Vec3(linearToSrgb(c.x), linearToSrgb(c.y), linearToSrgb(c.z));
}

// RGBA float (linear) -> display-referred RGB in place through the built-in operator (A is
// untouched). Non-finite values display as 0.
void displayEncodeInPlace(std::vector<float>& rgba, const DisplaySettings& display);

// Display-referred RGBA float, rows of `width` pixels -> RGB 8-bit, same pixel order.
// Non-finite values give 0. Dithered (ditherOffset at the pixel's x, y) when `dither`. The
// last step of every display path (the built-in one below, OpenColorIO's in
// assets/color_processor.h).
std::vector<uint8_t> quantizeDisplay8(const std::vector<float>& displayRgba, uint32_t width, bool dither);

// RGBA float (linear) -> RGB 8-bit through the built-in operator: displayEncodeInPlace, then
// quantizeDisplay8 with `display.dither`.
std::vector<uint8_t> encodeDisplay8(const std::vector<float>& rgba, uint32_t width,
                                    const DisplaySettings& display);

}  // namespace pt
