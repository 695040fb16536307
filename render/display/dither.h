#pragma once
// Dithering before 8-bit quantisation: a deterministic triangular-PDF offset of up to +-1 LSB
// per pixel, so smooth gradients do not band and the mean of a flat field stays the
// undithered value (a triangular dither also makes the error's variance independent of the
// signal). Keyed on the pixel position only: the same image always gives the same bytes.
//
// GLSL mirror (uint arithmetic wraps modulo 2^32 in GLSL 1.30+ exactly as here; every float
// step below is exact, so the GPU reproduces the CPU bit for bit):
//   uint hashU32(uint v) { v ^= v >> 16u; v *= 0x7feb352du; v ^= v >> 15u;
//                          v *= 0x846ca68bu; v ^= v >> 16u; return v; }
//   float ditherOffset(uvec2 p) {                        // p = pixel (x, y), y = image row
//       uint h = hashU32(p.x ^ hashU32(p.y + 0x68bc21ebu));
//       float a = (float(h & 0xffffu) + 0.5) / 65536.0;
//       float b = (float(h >> 16u) + 0.5) / 65536.0;
//       return a + b - 1.0; }
//   byte = clamp(floor(v * 255.0 + 0.5 + ditherOffset(p)), 0.0, 255.0)   // v display value
// (y counts image rows from the top, as the exported file does; a GL window's gl_FragCoord
// counts from the bottom, so the editor flips it to match.)
#include <cstdint>

#include "render/math/hd.h"
#include "render/sampling/hash.h"

namespace pt {

// In (-1, 1) LSB, triangular: the sum of two independent uniforms in (0, 1), minus 1.
// Mean exactly 0 over the 2^32 hash values.
PT_HD float ditherOffset(uint32_t x, uint32_t y) {
    const uint32_t h = hashU32(x ^ hashU32(y + 0x68bc21ebu));
    const float a = (float(h & 0xffffu) + 0.5f) / 65536.0f;
    const float b = (float(h >> 16) + 0.5f) / 65536.0f;
    return a + b - 1.0f;
}

// A display value (nominally [0, 1]) -> 8 bits, with `offset` LSB added before rounding
// (0: plain rounding; ditherOffset(x, y) to dither). NaN gives 0.
PT_HD uint8_t quantize8(float v, float offset) {
    const float q = floorf(v * 255.0f + 0.5f + offset);
    return uint8_t(q > 0.0f ? (q < 255.0f ? q : 255.0f) : 0.0f);
}

}  // namespace pt
