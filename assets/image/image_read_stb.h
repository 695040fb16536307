#pragma once
// Decoding images through stb_image (Debian's libstb), compiled in every build: what reads
// textures when PT_OIIO is OFF, and tested against OpenImageIO's decoder when it is ON.
// Same conventions as image_read.h: PNG, JPEG, BMP and TGA as RGBA8 (16-bit PNGs rounded to
// 8 bits exactly as OIIO rounds them), Radiance .hdr as RGBA32F, top row first, straight
// alpha, alpha 1 where the file has none.
#include <cstdint>
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace pt {

// Whether the stb decoder handles images with this extension (lower case, no dot).
bool stbDecodesExtension(const std::string& extension);

// Decodes whatever stb_image recognises in `bytes`. Throws InputError naming `name`.
Texture decodeTextureWithStb(const std::vector<uint8_t>& bytes, const std::string& name);

}  // namespace pt
