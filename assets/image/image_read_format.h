#pragma once
// What the image readers and writers share whichever library does the work (OpenImageIO or
// stb): telling formats apart by their bytes or file extension, the limits on what we decode,
// and the message for formats this build cannot handle.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pt {

// Largest image we decode: 2^27 texels is 512 MiB as RGBA8 and 2 GiB as RGBA32F. A header
// claiming more is far more likely broken or hostile than a real texture.
constexpr uint64_t kMaxImageTexels = uint64_t(1) << 27;
constexpr int kMaxImageSide = 1 << 16;

// Throws InputError naming `name` unless a width x height x depth image of `channels`
// channels is within the limits above (and is a 2D image with at least one channel).
void checkImageSize(const std::string& name, int width, int height, int depth, int channels);

// Throws InputError naming `path` unless `values` is width x height x channels: the writers
// read that many values, and fewer would be read past their end.
void checkPixelCount(const std::string& path, uint32_t width, uint32_t height, size_t channels,
                     size_t values);

// The format the bytes announce ("png", "jpg", "hdr", "exr", "tif", "webp", "gif", "bmp"),
// or "" when they announce none (formats without a signature, such as TGA). Throws
// InputError naming `name` for KTX2 (GPU-compressed) images, which nothing here decodes.
std::string sniffImageExtension(const std::vector<uint8_t>& bytes, const std::string& name);

// Throws InputError naming `name` unless the PNG's chunks all lie inside the bytes, up to IEND.
void checkPngChunks(const std::vector<uint8_t>& bytes, const std::string& name);

// The extension of `path` without the dot, lower case ("" when it has none).
std::string lowercaseExtension(const std::string& path);

// "<name>: EXR images need OpenImageIO, which this build does not have (configured with
// PT_OIIO=OFF)", for a format (given by its extension) that only OpenImageIO handles.
std::string needsOpenImageIoMessage(const std::string& name, const std::string& extension);

}  // namespace pt
