#include "assets/image/image_read_oiio.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>

#include "assets/image/image_read_format.h"
#include "assets/input_error.h"

namespace pt::oiio {
namespace {

// OIIO premultiplies alpha on read unless told not to; glTF and OBJ textures are straight
// alpha, and color in fully transparent texels must survive.
OIIO::ImageSpec readConfig() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

bool isFloatFormat(OIIO::TypeDesc type) {
    return type.basetype == OIIO::TypeDesc::FLOAT || type.basetype == OIIO::TypeDesc::HALF ||
           type.basetype == OIIO::TypeDesc::DOUBLE;
}

// Gray, gray+alpha and RGB become RGBA (alpha 1 where the file has none).
template <class T>
std::vector<T> expandToRgba(const std::vector<T>& in, size_t texels, int channels, T one) {
    std::vector<T> out(texels * 4);
    for (size_t i = 0; i < texels; ++i) {
        const T* src = &in[i * size_t(channels)];
        T* dst = &out[i * 4];
        const bool gray = channels <= 2;
        dst[0] = src[0];
        dst[1] = gray ? src[0] : src[1];
        dst[2] = gray ? src[0] : src[2];
        dst[3] = channels == 2 ? src[1] : channels == 4 ? src[3] : one;
    }
    return out;
}

Texture decodeOpened(OIIO::ImageInput& in, const std::string& name) {
    const OIIO::ImageSpec& spec = in.spec();
    checkImageSize(name, spec.width, spec.height, spec.depth, spec.nchannels);
    Texture texture;
    texture.name = name;
    texture.width = uint32_t(spec.width);
    texture.height = uint32_t(spec.height);
    const size_t texels = size_t(spec.width) * size_t(spec.height);
    const int channels = std::min(spec.nchannels, 4);
    const bool hdr = isFloatFormat(spec.format);
    bool ok;
    if (hdr) {
        std::vector<float> raw(texels * size_t(channels));
        ok = in.read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data());
        texture.format = TexelFormat::RGBA32F;
        texture.texelsF = expandToRgba(raw, texels, channels, 1.0f);
    } else {
        // 16-bit PNGs land here too, rounded to 8 bits: base color and normal maps need no more.
        std::vector<uint8_t> raw(texels * size_t(channels));
        ok = in.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data());
        texture.format = TexelFormat::RGBA8;
        texture.texels8 = expandToRgba(raw, texels, channels, uint8_t(255));
    }
    if (!ok) throw InputError(name + ": cannot decode: " + in.geterror());
    return texture;
}

// Reads through an in-memory proxy; nullptr when OIIO's reader for `extension` cannot.
// (ImageInput::open(name, config, proxy) looks for the file on disk in OIIO 2.4; creating
// the reader and handing it the proxy first reads from memory.)
std::unique_ptr<OIIO::ImageInput> openInMemory(const std::string& extension,
                                               OIIO::Filesystem::IOMemReader& memory,
                                               const OIIO::ImageSpec& config, const std::string& name) {
    const std::string fakeName = "memory." + extension;
    auto in = OIIO::ImageInput::create(fakeName, false, &config, &memory);
    if (!in) throw InputError(name + ": cannot decode: " + OIIO::geterror());
    if (!in->supports("ioproxy")) return nullptr;
    in->set_ioproxy(&memory);
    OIIO::ImageSpec spec;
    if (!in->open(fakeName, spec, config)) {
        throw InputError(name + ": cannot decode: " + in->geterror());
    }
    return in;
}

}  // namespace

Texture decodeTexture(const std::vector<uint8_t>& bytes, const std::string& extension,
                      const std::string& name, const std::string& filePath) {
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    const OIIO::ImageSpec config = readConfig();
    std::unique_ptr<OIIO::ImageInput> in = openInMemory(extension, memory, config, name);
    if (!in && !filePath.empty()) {
        in = OIIO::ImageInput::open(filePath, &config);
        if (!in) throw InputError(name + ": cannot decode: " + OIIO::geterror());
    }
    if (!in) throw InputError(name + ": " + extension + " images cannot be read from memory");
    return decodeOpened(*in, name);
}

}  // namespace pt::oiio
