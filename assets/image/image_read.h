#pragma once
// Decoding images into Textures: 8-bit formats (PNG, JPEG) as RGBA8, HDR formats (.hdr, .exr)
// as RGBA32F, top row first. Texel data stays as stored in the file (no sRGB decode here: the
// sampling slot decides). Through OpenImageIO, or with PT_OIIO=OFF through stb_image, which
// reads PNG, JPEG, BMP, TGA and Radiance HDR, and throws for EXR and the rest. Throws
// InputError naming the image when it cannot be decoded; callers that can fall back (glTF
// textures) catch it and warn.
#include <cstdint>
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace pt {

Texture readTextureFile(const std::string& path);

// `name` identifies the image in messages (e.g. "model.glb: images[2]"); `mimeType` may be "".
Texture decodeTextureFromMemory(const std::vector<uint8_t>& bytes, const std::string& name,
                                const std::string& mimeType = "");

}  // namespace pt
