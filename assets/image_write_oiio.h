#pragma once
// The OpenImageIO side of image_write.h (compiled only when PT_OIIO is ON). The writers fill
// `file` (the temporary of an atomic write; its extension picks the format) and name `path`,
// the file users asked for, in their InputErrors.
#include <cstdint>
#include <string>
#include <vector>

#include "assets/image_write.h"

namespace pt {

void writeExrWithOiio(const std::string& file, const std::string& path, uint32_t width,
                      uint32_t height, const float* rgba, const ImageMetadata& metadata);

void writeDisplayImageWithOiio(const std::string& file, const std::string& path, uint32_t width,
                               uint32_t height, const uint8_t* rgb, const ImageMetadata& metadata);

std::vector<float> readImageRgbaWithOiio(const std::string& path, uint32_t& width, uint32_t& height);

}  // namespace pt
