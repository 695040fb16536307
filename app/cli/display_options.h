#pragma once
// pt-render's display flags: how the --png output turns the linear render into display
// pixels (DESIGN.md "Display and color").
//   --ocio CONFIG  --display NAME  --view NAME  --look NAME   an OpenColorIO view
//   --tonemap standard|reinhard|aces-fitted|agx [--white-point W]   a built-in operator instead
//   --exposure STOPS   before either;   --no-dither   plain rounding to 8 bits
// Without flags: the scene's "color" setting, else the config's default display and view
// (the shipped config: sRGB / Standard, the plain sRGB encoding).
#include <optional>
#include <set>
#include <string>

#include "assets/color/color_processor.h"
#include "assets/image/image_write.h"
#include "cli/cli_options.h"
#include "render/scene/scene.h"

namespace pt::cli {

struct DisplayRequest {
    std::string ocioConfig;                // --ocio ("" = the scene's, $OCIO, or the shipped one)
    ViewTransform view;                    // --display, --view, --look ("" = not given)
    std::optional<ToneMapper> toneMapper;  // --tonemap: a built-in operator, no OpenColorIO
    float whitePoint = DisplaySettings{}.whitePoint;
    float exposureStops = 0.0f;
    bool dither = true;

    bool anyGiven = false;  // whether any display flag was given
};

// --ocio --display --view --look --tonemap --white-point --exposure
const std::set<std::string>& displayValuedFlags();
const std::set<std::string>& displaySwitches();  // --no-dither
// Throws UsageError for a bad value or combination (--tonemap with OpenColorIO flags,
// --white-point without --tonemap reinhard, OpenColorIO flags in a build without it).
DisplayRequest parseDisplayOptions(const Options& options);

// The processor for `request` over a scene viewed with `scene`: the built-in operator when
// --tonemap is given (or the build has no OpenColorIO), else the OpenColorIO view. The
// scene's display / view / look apply where no flag replaces them, and only with the scene's
// own config (not under --ocio). Throws InputError for a bad config or an unknown name.
DisplayProcessor makeDisplayProcessor(const DisplayRequest& request, const ColorSettings& scene);

}  // namespace pt::cli
