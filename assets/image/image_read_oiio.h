#pragma once
// Decoding images through OpenImageIO, with the conventions of image_read.h. Compiled only into
// the pt_oiio module (oiio_image_io.h loads it); callers reach it through oiioImageIo().
#include <cstdint>
#include <string>
#include <vector>

#include "render/scene/scene.h"

namespace pt::oiio {

// `extension` (lower case, no dot) picks OIIO's reader; `filePath` (may be "") is where the
// bytes came from, for formats OIIO reads only from files. Throws InputError naming `name`.
Texture decodeTexture(const std::vector<uint8_t>& bytes, const std::string& extension,
                      const std::string& name, const std::string& filePath);

}  // namespace pt::oiio
