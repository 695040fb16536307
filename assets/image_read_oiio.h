#pragma once
// Decoding images through OpenImageIO (compiled only when PT_OIIO is ON): every format it
// knows, with the conventions of image_read.h.
#include <cstdint>
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace pt {

// `extension` (lower case, no dot) picks OIIO's reader; `filePath` (may be "") is where the
// bytes came from, for formats OIIO reads only from files. Throws InputError naming `name`.
Texture decodeTextureWithOiio(const std::vector<uint8_t>& bytes, const std::string& extension,
                              const std::string& name, const std::string& filePath);

}  // namespace pt
