#include "assets/image_metadata.h"

#include "assets/image_read_format.h"
#include "assets/input_error.h"
#if PT_HAVE_OIIO
#include <OpenImageIO/imageio.h>
#endif

namespace pt {

ImageMetadata readImageMetadata(const std::string& path) {
#if PT_HAVE_OIIO
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError(path + ": cannot read image: " + OIIO::geterror());
    ImageMetadata metadata;
    for (const OIIO::ParamValue& p : in->spec().extra_attribs) {
        metadata.emplace_back(p.name().string(), p.get_string());
    }
    return metadata;
#else
    throw InputError(needsOpenImageIoMessage(path, lowercaseExtension(path)));
#endif
}

}  // namespace pt
