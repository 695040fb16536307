#pragma once
// Encoding display-referred 8-bit RGB through stb_image_write (Debian's libstb), compiled in
// every build: what writes PNG and JPEG when PT_OIIO is OFF. The pixels are written exactly as
// given (the display transform and quantisation happened before, as for OpenImageIO).
#include <cstdint>
#include <string>
#include <vector>

#include "assets/image/image_write.h"

namespace pt {

// JPEG quality, as OpenImageIO's default (libjpeg's 1..100 scale).
constexpr int kJpegQuality = 98;

// A PNG file's bytes, marked sRGB with the gAMA, sRGB and cHRM chunks OpenImageIO writes, and
// `metadata` as tEXt chunks (pairs whose key PNG cannot store, empty or past 79 bytes or with
// a NUL, are left out). `rgb`: width x height x 3 bytes, top row first. Throws InputError
// naming `name`.
std::vector<uint8_t> encodePngWithStb(const std::string& name, uint32_t width, uint32_t height,
                                      const std::vector<uint8_t>& rgb, const ImageMetadata& metadata);

// A baseline JPEG file's bytes (4:4:4 chroma at this quality); JPEG keeps no metadata here.
std::vector<uint8_t> encodeJpegWithStb(const std::string& name, uint32_t width, uint32_t height,
                                       const std::vector<uint8_t>& rgb, int quality = kJpegQuality);

}  // namespace pt
