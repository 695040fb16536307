#pragma once
// Writing renders, atomically (temp file, then rename), through OpenImageIO; with PT_OIIO=OFF
// through stb_image_write, which writes PNG and JPEG, and EXR and TIFF throw InputError.
// EXRs with AOV layers and half channels: exr_layers.h.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pt {

// Metadata written as string attributes (EXR header / PNG text chunks; JPEG drops it in the
// PT_OIIO=OFF build).
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// The attributes every render carries: its samples per pixel and render time, the backend,
// the scene and the program that made it (pt:spp, pt:render_seconds, pt:backend, pt:scene,
// Software). `renderSeconds` is written as given, so callers choose its precision.
ImageMetadata renderMetadata(uint32_t spp, const std::string& renderSeconds, const std::string& backend,
                             const std::string& scene, const std::string& software);

// Scene-linear RGBA float as a float EXR. Throws InputError naming `path` on failure.
void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba,
              const ImageMetadata& metadata = {});

// Display-referred 8-bit RGB (PNG, JPEG or TIFF by extension).
void writeDisplayImage(const std::string& path, uint32_t width, uint32_t height,
                       const std::vector<uint8_t>& rgb, const ImageMetadata& metadata = {});

// Reads any image OIIO knows as RGBA float (for tests and references): the channels named R,
// G, B and A where it has them (a layered EXR's beauty), else its first ones. With PT_OIIO=OFF,
// what readTextureFile reads. Throws InputError.
std::vector<float> readImageRgba(const std::string& path, uint32_t& width, uint32_t& height);

}  // namespace pt
