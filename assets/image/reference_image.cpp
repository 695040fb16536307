#include "assets/image/reference_image.h"

#include <cstdlib>

#include "assets/image/image_metadata.h"
#include "assets/image/image_write.h"
#include "assets/input_error.h"

namespace pt {

ReferenceImage loadReferenceImage(const std::string& path) {
    ReferenceImage reference;
    reference.path = path;
    reference.rgba = readImageRgba(path, reference.width, reference.height);
    ImageMetadata metadata;
    try {
        metadata = readImageMetadata(path);
    } catch (const InputError&) {
        // Pixels without metadata (a build without OpenImageIO): the noise stays unknown.
    }
    for (const auto& [key, value] : metadata) {
        if (key == "pt:noise_relmse") reference.noiseRelMse = std::strtod(value.c_str(), nullptr);
    }
    return reference;
}

}  // namespace pt
