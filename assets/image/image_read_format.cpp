#include "assets/image/image_read_format.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>

#include "assets/input_error.h"

namespace pt {
namespace {

bool startsWith(const std::vector<uint8_t>& bytes, const char* magic, size_t n, size_t at = 0) {
    return bytes.size() >= at + n && std::memcmp(bytes.data() + at, magic, n) == 0;
}

uint32_t bigEndian32(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

}  // namespace

void checkImageSize(const std::string& name, int width, int height, int depth, int channels) {
    if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide ||
        uint64_t(width) * uint64_t(height) > kMaxImageTexels || depth > 1 || channels <= 0) {
        throw InputError(name + ": unsupported image size " + std::to_string(width) + "x" +
                         std::to_string(height) + "x" + std::to_string(depth) + " with " +
                         std::to_string(channels) + " channels");
    }
}

void checkPixelCount(const std::string& path, uint32_t width, uint32_t height, size_t channels,
                     size_t values) {
    if (values != size_t(width) * height * channels) {
        throw InputError(path + ": " + std::to_string(values) + " pixel values for a " +
                         std::to_string(width) + "x" + std::to_string(height) + "x" +
                         std::to_string(channels) + " image");
    }
}

std::string sniffImageExtension(const std::vector<uint8_t>& bytes, const std::string& name) {
    if (startsWith(bytes, "\x89PNG\r\n\x1a\n", 8)) return "png";
    if (startsWith(bytes, "\xff\xd8\xff", 3)) return "jpg";
    if (startsWith(bytes, "#?RADIANCE", 10) || startsWith(bytes, "#?RGBE", 6)) return "hdr";
    if (startsWith(bytes, "\x76\x2f\x31\x01", 4)) return "exr";
    if (startsWith(bytes, "II*\0", 4) || startsWith(bytes, "MM\0*", 4)) return "tif";
    if (startsWith(bytes, "RIFF", 4) && startsWith(bytes, "WEBP", 4, 8)) return "webp";
    if (startsWith(bytes, "GIF8", 4)) return "gif";
    if (startsWith(bytes, "BM", 2)) return "bmp";
    if (startsWith(bytes, "\xabKTX 20\xbb", 8)) {
        throw InputError(name + ": KTX2 (GPU-compressed) images are not supported");
    }
    return "";
}

// Checked before decoding because when libpng runs out of input inside OIIO 2.4's read
// callback, OIIO leaks its error string; stb gets the same clear message.
void checkPngChunks(const std::vector<uint8_t>& bytes, const std::string& name) {
    size_t at = 8;
    while (at + 12 <= bytes.size()) {
        const uint64_t length = bigEndian32(&bytes[at]);
        if (at + 12 + length > bytes.size()) break;
        if (std::memcmp(&bytes[at + 4], "IEND", 4) == 0) return;
        at += 12 + size_t(length);
    }
    throw InputError(name + ": PNG data is truncated");
}

std::string lowercaseExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    if (!extension.empty()) extension.erase(0, 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

std::string needsOpenImageIoMessage(const std::string& name, const std::string& extension) {
    std::string format = extension;
    if (format == "tif" || format == "tx") format = "tiff";
    if (format == "webp") {
        format = "WebP";
    } else {
        std::transform(format.begin(), format.end(), format.begin(),
                       [](unsigned char c) { return char(std::toupper(c)); });
    }
    return name + ": " + format +
           " images need OpenImageIO, which this build does not have (configured with "
           "PT_OIIO=OFF)";
}

}  // namespace pt
