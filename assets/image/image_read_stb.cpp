#include "assets/image/image_read_stb.h"

#include <stb/stb_image.h>

#include <climits>
#include <cstring>
#include <memory>

#include "assets/image/image_read_format.h"
#include "assets/input_error.h"

namespace pt {
namespace {

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};
template <class T>
using StbPixels = std::unique_ptr<T, StbFree>;

// The same rounding as OpenImageIO's UINT16 -> UINT8 conversion (v * 255 / 65535, to nearest).
uint8_t roundTo8Bits(stbi_us v) { return uint8_t((uint32_t(v) + 128u) / 257u); }

[[noreturn]] void throwDecodeError(const std::string& name) {
    const char* reason = stbi_failure_reason();
    throw InputError(name + ": cannot decode: " + (reason ? reason : "unknown stb_image error"));
}

// stb fills in the size again when it decodes; it must be the size its header check passed.
template <class T>
void checkDecoded(const StbPixels<T>& pixels, int width, int height, int infoWidth, int infoHeight,
                  const std::string& name) {
    if (!pixels) throwDecodeError(name);
    if (width != infoWidth || height != infoHeight) {
        throw InputError(name + ": cannot decode: image size changed between header and pixels");
    }
}

// stb_image chooses its decoder from the bytes, among more formats than stbDecodesExtension
// names, and Debian 12's stb_image 2.27 has known bugs in some: a 16-bit PGM is converted as
// if it had 8 bits, so its texels would be read past the end of stb's buffer (CVE-2021-42716).
// Bytes with the signature of another format stb reads (GIF, PSD, PIC, PNM) never reach it,
// whatever the file is called; TGA has no signature and is what remains (no TGA starts with
// one of these: its second byte, the colour map type, is 0 or 1).
bool hasOtherStbSignature(const std::vector<uint8_t>& bytes) {
    const auto startsWith = [&](const char* magic, size_t n) {
        return bytes.size() >= n && std::memcmp(bytes.data(), magic, n) == 0;
    };
    return startsWith("GIF8", 4) || startsWith("8BPS", 4) || startsWith("\x53\x80\xf6\x34", 4) ||
           startsWith("P5", 2) || startsWith("P6", 2);
}

// Where the pixels of a Radiance file start, as stb_image's header parser finds them: after
// the first line, the header lines up to an empty one (or one starting with a NUL byte, which
// stb reads as empty), and the resolution line. bytes.size() when the file ends before.
size_t hdrPixelsStart(const std::vector<uint8_t>& bytes) {
    size_t pos = 0;
    const auto nextLine = [&] {  // returns whether the line was empty
        const size_t start = pos;
        while (pos < bytes.size() && bytes[pos] != '\n') ++pos;
        const bool empty = pos == start || bytes[start] == 0;
        if (pos < bytes.size()) ++pos;
        return empty;
    };
    nextLine();  // "#?RADIANCE"
    while (pos < bytes.size() && !nextLine()) {
    }
    nextLine();  // "-Y <height> +X <width>"
    return pos;
}

// Debian 12's libstb (stb_image 2.27) reads a run-length encoded Radiance row that the file
// ends inside of as endless zero-length literals and never returns (CVE-2021-42715, stb issue
// #1224; 2.28 refuses a count of 0). So the rows are walked here first, as stb_image will
// read them, and a count of 0, which the file's end reads as, is refused. Whatever else is
// wrong with the rows (a run past the row's end, a length other than the width) stb reports.
//
// Rows stb reads flat (4 bytes a pixel) must be in the file: stb reads a cut-off file's missing
// pixels as zeros, so a few bytes claiming 11111 x 11111 pixels had it allocate 2 GB (twice:
// its buffer and ours), which the fuzzer found.
void checkHdrRunLengths(const std::vector<uint8_t>& bytes, int width, int height, const std::string& name) {
    size_t pos = hdrPixelsStart(bytes);
    // The rows from `row` on, read flat from `start`, end inside the file.
    const auto flatRest = [&](int row, size_t start) {
        const uint64_t needed = uint64_t(height - row) * uint64_t(width) * 4u;
        if (start > bytes.size() || bytes.size() - start < needed) {
            throw InputError(name + ": cannot decode: the pixels end before row " + std::to_string(height) +
                             " (cut off at row " + std::to_string(row) + " or after)");
        }
    };
    if (width < 8 || width >= 32768) return flatRest(0, pos);  // stb reads such rows flat, never encoded
    const auto next = [&]() -> int { return pos < bytes.size() ? bytes[pos++] : 0; };  // as stb
    for (int row = 0; row < height; ++row) {
        const size_t rowStart = pos;
        const int c1 = next(), c2 = next(), high = next();
        // Not an encoded row: stb reads the rest as flat pixels.
        if (c1 != 2 || c2 != 2 || (high & 0x80)) return flatRest(row, rowStart);
        if (((high << 8) | next()) != width) return;
        for (int channel = 0; channel < 4; ++channel) {
            for (int x = 0; x < width;) {
                int count = next();
                if (count == 0) {
                    throw InputError(name + ": cannot decode: bad run-length data in row " +
                                     std::to_string(row) + " (cut off, or a count of 0)");
                }
                const bool run = count > 128;
                if (run) count -= 128;
                if (count > width - x) return;
                if (run) {
                    next();
                } else {
                    pos += size_t(count);
                }
                x += count;
            }
        }
    }
}

}  // namespace

bool stbDecodesExtension(const std::string& extension) {
    for (const char* known : {"png", "jpg", "jpeg", "jpe", "jfif", "bmp", "tga", "hdr", "rgbe"}) {
        if (extension == known) return true;
    }
    return false;
}

Texture decodeTextureWithStb(const std::vector<uint8_t>& bytes, const std::string& name) {
    if (bytes.empty()) throw InputError(name + ": image is empty");
    if (bytes.size() > size_t(INT_MAX)) throw InputError(name + ": image file is too large");
    if (hasOtherStbSignature(bytes)) {
        throw InputError(name + ": cannot decode: not a PNG, JPEG, BMP, TGA or Radiance HDR image");
    }
    const stbi_uc* data = bytes.data();
    const int length = int(bytes.size());
    // libstb is shared with other users (tinygltf); rows stay top first whatever they set.
    stbi_set_flip_vertically_on_load_thread(0);
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels)) throwDecodeError(name);
    checkImageSize(name, width, height, 1, channels);

    Texture texture;
    texture.name = name;
    texture.width = uint32_t(width);
    texture.height = uint32_t(height);
    const size_t values = size_t(width) * size_t(height) * 4;
    int w = 0, h = 0;
    if (stbi_is_hdr_from_memory(data, length)) {
        checkHdrRunLengths(bytes, width, height, name);
        StbPixels<float> pixels(stbi_loadf_from_memory(data, length, &w, &h, &channels, 4));
        checkDecoded(pixels, w, h, width, height, name);
        texture.format = TexelFormat::RGBA32F;
        texture.texelsF.assign(pixels.get(), pixels.get() + values);
    } else if (stbi_is_16_bit_from_memory(data, length)) {
        StbPixels<stbi_us> pixels(stbi_load_16_from_memory(data, length, &w, &h, &channels, 4));
        checkDecoded(pixels, w, h, width, height, name);
        texture.format = TexelFormat::RGBA8;
        texture.texels8.resize(values);
        for (size_t i = 0; i < values; ++i) texture.texels8[i] = roundTo8Bits(pixels.get()[i]);
    } else {
        StbPixels<stbi_uc> pixels(stbi_load_from_memory(data, length, &w, &h, &channels, 4));
        checkDecoded(pixels, w, h, width, height, name);
        texture.format = TexelFormat::RGBA8;
        texture.texels8.assign(pixels.get(), pixels.get() + values);
    }
    return texture;
}

}  // namespace pt
