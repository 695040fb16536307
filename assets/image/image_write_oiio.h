#pragma once
// The OpenImageIO side of image_write.h, exr_layers.h and image_metadata.h. Compiled only into
// the pt_oiio module (oiio_image_io.h loads it); callers reach it through oiioImageIo(). The writers fill
// `file` (the temporary of an atomic write; its extension picks the format) and name `path`, the file users
// asked for, in their InputErrors.
#include <cstdint>
#include <string>
#include <vector>

#include "assets/image/exr_layers.h"
#include "assets/image/image_write.h"

namespace pt::oiio {

// One EXR of `channels` (each at its own pixel type), zip-compressed.
void writeExrChannels(const std::string& file, const std::string& path, uint32_t width, uint32_t height,
                      const std::vector<ExrChannelSource>& channels, const ImageMetadata& metadata);

void writeDisplayImage(const std::string& file, const std::string& path, uint32_t width, uint32_t height,
                       const uint8_t* rgb, const ImageMetadata& metadata);

// The channels named R, G, B and A where the image has them (a layered EXR's beauty), else its
// first channels; gray images fill R, G and B.
std::vector<float> readImageRgba(const std::string& path, uint32_t& width, uint32_t& height);

ExrImage readExrChannels(const std::string& path);

// Every attribute of the image's header as text.
ImageMetadata readImageMetadata(const std::string& path);

}  // namespace pt::oiio
