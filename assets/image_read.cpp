#include "assets/image_read.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <memory>

#include "assets/input_error.h"

namespace pt {
namespace {

// Largest image we decode: 2^27 texels is 512 MiB as RGBA8 and 2 GiB as RGBA32F. A header
// claiming more is far more likely broken or hostile than a real texture.
constexpr uint64_t kMaxTexels = uint64_t(1) << 27;
constexpr int kMaxSide = 1 << 16;

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
    if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxSide || spec.height > kMaxSide ||
        uint64_t(spec.width) * uint64_t(spec.height) > kMaxTexels || spec.depth > 1 ||
        spec.nchannels <= 0) {
        throw InputError(name + ": unsupported image size " + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + "x" + std::to_string(spec.depth) +
                         " with " + std::to_string(spec.nchannels) + " channels");
    }
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

bool startsWith(const std::vector<uint8_t>& bytes, const char* magic, size_t n, size_t at = 0) {
    return bytes.size() >= at + n && std::memcmp(bytes.data() + at, magic, n) == 0;
}

// OIIO picks its reader by file extension; memory has none, so the bytes say what they are.
std::string formatExtension(const std::vector<uint8_t>& bytes, const std::string& mimeType,
                            const std::string& name) {
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
    throw InputError(name + ": not an image format we can decode" +
                     (mimeType.empty() ? std::string() : " (mimeType '" + mimeType + "')"));
}

}  // namespace

Texture readTextureFile(const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw InputError(path + ": image file not found");
    }
    const OIIO::ImageSpec config = readConfig();
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) throw InputError(path + ": cannot open image: " + OIIO::geterror());
    Texture texture = decodeOpened(*in, path);
    texture.name = name;
    texture.sourcePath = path;
    return texture;
}

Texture decodeTextureFromMemory(const std::vector<uint8_t>& bytes, const std::string& name,
                                const std::string& mimeType) {
    if (bytes.empty()) throw InputError(name + ": image is empty");
    const std::string fakeName = "memory." + formatExtension(bytes, mimeType, name);
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    const OIIO::ImageSpec config = readConfig();
    // ImageInput::open(name, config, proxy) looks for the file on disk in OIIO 2.4; creating
    // the reader and handing it the proxy first reads from memory.
    auto in = OIIO::ImageInput::create(fakeName, false, &config, &memory);
    if (!in) throw InputError(name + ": cannot decode: " + OIIO::geterror());
    if (!in->supports("ioproxy")) {
        throw InputError(name + ": " + in->format_name() + " images cannot be read from memory");
    }
    in->set_ioproxy(&memory);
    OIIO::ImageSpec spec;
    if (!in->open(fakeName, spec, config)) {
        throw InputError(name + ": cannot decode: " + in->geterror());
    }
    return decodeOpened(*in, name);
}

}  // namespace pt
