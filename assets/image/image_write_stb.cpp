#include "assets/image/image_write_stb.h"

#include <stb/stb_image_write.h>

#include <array>

#include "assets/image/image_read_format.h"
#include "assets/input_error.h"

namespace pt {
namespace {

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<uint8_t>*>(context);
    const auto* bytes = static_cast<const uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

// stb_image_write counts bytes in ints; the reader's limits keep every count far below.
void checkSize(const std::string& name, uint32_t width, uint32_t height, uint32_t maxSide,
               const std::vector<uint8_t>& rgb) {
    if (width == 0 || height == 0 || width > maxSide || height > maxSide ||
        uint64_t(width) * height > kMaxImageTexels) {
        throw InputError(name + ": cannot write a " + std::to_string(width) + "x" + std::to_string(height) +
                         " image in this format");
    }
    if (rgb.size() != size_t(width) * height * 3) {
        throw InputError(name + ": " + std::to_string(rgb.size()) + " bytes of pixels for a " +
                         std::to_string(width) + "x" + std::to_string(height) + " RGB image");
    }
}

uint32_t crc32(const uint8_t* data, size_t size) {
    static const std::array<uint32_t, 256> table = [] {
        std::array<uint32_t, 256> t{};
        for (uint32_t n = 0; n < 256; ++n) {
            uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xffu] ^ (c >> 8);
    return c ^ 0xffffffffu;
}

void appendBigEndian32(std::vector<uint8_t>& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

void appendChunk(std::vector<uint8_t>& out, const char type[4], const std::vector<uint8_t>& data) {
    appendBigEndian32(out, uint32_t(data.size()));
    const size_t typeAt = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    appendBigEndian32(out, crc32(&out[typeAt], 4 + data.size()));
}

// What libpng's png_set_sRGB_gAMA_and_cHRM writes for OpenImageIO: gamma 1/2.2 (45455),
// rendering intent 3 and the Rec.709 chromaticities, so both builds mark files alike.
std::vector<uint8_t> srgbChunks() {
    std::vector<uint8_t> out;
    appendChunk(out, "gAMA", {0x00, 0x00, 0xb1, 0x8f});
    appendChunk(out, "sRGB", {0x03});
    std::vector<uint8_t> chromaticities;
    for (uint32_t v : {31270u, 32900u, 64000u, 33000u, 30000u, 60000u, 15000u, 6000u}) {
        appendBigEndian32(chromaticities, v);
    }
    appendChunk(out, "cHRM", chromaticities);
    return out;
}

bool pngCanStoreText(const std::string& key, const std::string& value) {
    return !key.empty() && key.size() <= 79 && key.find('\0') == std::string::npos &&
           value.find('\0') == std::string::npos;
}

}  // namespace

std::vector<uint8_t> encodePngWithStb(const std::string& name, uint32_t width, uint32_t height,
                                      const std::vector<uint8_t>& rgb, const ImageMetadata& metadata) {
    checkSize(name, width, height, uint32_t(kMaxImageSide), rgb);
    std::vector<uint8_t> png;
    if (!stbi_write_png_to_func(appendBytes, &png, int(width), int(height), 3, rgb.data(), int(width) * 3)) {
        throw InputError(name + ": cannot encode PNG");
    }
    // stb writes the signature, IHDR, IDAT and IEND; the other chunks go after IHDR.
    constexpr size_t kAfterHeader = 8 + 12 + 13;
    if (png.size() < kAfterHeader) throw InputError(name + ": cannot encode PNG");
    std::vector<uint8_t> chunks = srgbChunks();
    for (const auto& [key, value] : metadata) {
        if (!pngCanStoreText(key, value)) continue;
        std::vector<uint8_t> text(key.begin(), key.end());
        text.push_back(0);
        text.insert(text.end(), value.begin(), value.end());
        appendChunk(chunks, "tEXt", text);
    }
    png.insert(png.begin() + std::ptrdiff_t(kAfterHeader), chunks.begin(), chunks.end());
    return png;
}

std::vector<uint8_t> encodeJpegWithStb(const std::string& name, uint32_t width, uint32_t height,
                                       const std::vector<uint8_t>& rgb, int quality) {
    checkSize(name, width, height, 65535, rgb);
    std::vector<uint8_t> jpeg;
    if (!stbi_write_jpg_to_func(appendBytes, &jpeg, int(width), int(height), 3, rgb.data(), quality)) {
        throw InputError(name + ": cannot encode JPEG");
    }
    return jpeg;
}

}  // namespace pt
