#pragma once
// The display path on the CPU, for file export: linear RGBA (scene-referred, Rec.709) ->
// display-referred values -> optional dither -> 8 bits. Either an OpenColorIO view (exposure
// in stops, then the config's scene_linear -> display / view / look processor) or one of the
// built-in operators (render/display/display_transform.h). The editor does the same on the
// GPU: exposure in GLSL, then the function of makeGpuColorShader (assets/color_gpu_shader.h)
// built from the same processor, then the same dither (render/display/dither.h).
//
// Non-finite input values display as 0 (after exposure, before the transform).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "assets/color/color_config.h"
#include "assets/image/image_write.h"
#include "render/display/display_transform.h"

namespace pt {

class DisplayProcessor {
public:
    // OpenColorIO view. `view` must be complete (ColorConfig::resolve); throws InputError when
    // OpenColorIO cannot build the processor. Only with PT_HAVE_OCIO (the constructor is not
    // compiled without it).
    DisplayProcessor(const ColorConfig& config, const ViewTransform& view, float exposureStops);
    // A built-in operator, exposure `builtin.exposureStops` (`builtin.dither` is not read:
    // encode8 takes the choice).
    explicit DisplayProcessor(const DisplaySettings& builtin);

    // RGBA float (linear) -> display-referred RGB in place, nominally [0, 1] (OpenColorIO
    // views may leave values outside; encode8 clamps). A is untouched.
    void applyInPlace(std::vector<float>& rgba) const;
    // RGBA float (linear), rows of `width` pixels -> RGB 8-bit display values, same pixel
    // order. `dither`: triangular +-1 LSB dither keyed on the pixel position (ditherOffset).
    std::vector<uint8_t> encode8(const std::vector<float>& rgba, uint32_t width, bool dither) const;

    // "OCIO config.ocio: sRGB / AgX" (plus " / look NAME", ", exposure +1 stops" when set),
    // or "built-in: reinhard (white 4)".
    std::string describe() const;
    bool usesOcio() const { return bool(ocio_); }
    const std::string& configPath() const { return configPath_; }  // "" for built-in
    const ViewTransform& view() const { return view_; }            // empty for built-in

private:
    DisplaySettings builtin_;
    float exposureStops_ = 0.0f;
    // The OpenColorIO CPU processor over `pixels` RGBA pixels (RGB only); empty: built-in.
    std::function<void(float* rgba, size_t pixels)> ocio_;
    std::string configPath_;
    ViewTransform view_;
};

// What an exported image records of its display path: "pt:ocio_config" (the config's path;
// OpenColorIO views only), "pt:view" (describe()), "pt:dither" ("on"/"off"). EXRs carry it too:
// they stay scene-linear, and it says how the render was meant to be seen.
ImageMetadata displayMetadata(const DisplayProcessor& display, bool dither);

}  // namespace pt
