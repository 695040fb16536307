#pragma once
// The AgX sigmoid (render/display/agx.h: agxSigmoid) as an OpenColorIO 1D LUT: the curve the
// shipped config's "AgX" view cannot build from its analytic transforms. The committed file is
// scenes/ocio/luts/agx_sigmoid.spi1d; tests/assets/color_agx_lut_test.cpp checks that it is
// byte for byte what this writes, and rewrites it when run with PT_REGENERATE_AGX_LUT=1.
#include <cstdint>
#include <string>

namespace pt {

// Linear interpolation between 1024 samples of the polynomial errs by under 1e-6 (the error is
// at most h^2 / 8 max|f''| with h = 1/1023 and |f''| < 7.5 on [0, 1]), far below the 1/255 of
// an 8-bit display step.
constexpr uint32_t kAgxLutEntries = 1024;

// Sony Pictures Imageworks .spi1d text: domain [0, 1], `entries` samples of agxSigmoid at
// i / (entries - 1), one component, each printed with 9 significant digits (exact for a
// float). The same text on every platform: the curve is float arithmetic without contraction.
std::string agxSigmoidSpi1d(uint32_t entries = kAgxLutEntries);

}  // namespace pt
