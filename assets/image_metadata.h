#pragma once
// Reading back the string attributes writeExr stores (e.g. pt:spp, pt:noise_relmse of a
// reference render), for tools that compare against a render. Through OpenImageIO; the
// PT_OIIO=OFF build, which cannot read EXR, throws InputError.
#include <string>

#include "assets/image_write.h"

namespace pt {

// Every attribute of the image's header as text. Throws InputError naming `path`.
ImageMetadata readImageMetadata(const std::string& path);

}  // namespace pt
