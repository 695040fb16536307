#include "assets/image_read_stb.h"

#include <stb/stb_image.h>

#include <climits>
#include <memory>

#include "assets/image_read_format.h"
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
void checkDecoded(const StbPixels<T>& pixels, int width, int height, int infoWidth,
                  int infoHeight, const std::string& name) {
    if (!pixels) throwDecodeError(name);
    if (width != infoWidth || height != infoHeight) {
        throw InputError(name + ": cannot decode: image size changed between header and pixels");
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
