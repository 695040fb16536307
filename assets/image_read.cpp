#include "assets/image_read.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
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
// "" when they do not (formats without a signature, such as TGA).
std::string sniffExtension(const std::vector<uint8_t>& bytes, const std::string& name) {
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

uint32_t bigEndian32(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

// A PNG's chunks must all lie inside the bytes, up to IEND. Checked here because when libpng
// runs out of input inside OIIO 2.4's read callback, OIIO leaks its error string.
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

// Reads through an in-memory proxy; nullptr when OIIO's reader for `extension` cannot.
// (ImageInput::open(name, config, proxy) looks for the file on disk in OIIO 2.4; creating
// the reader and handing it the proxy first reads from memory.)
std::unique_ptr<OIIO::ImageInput> openInMemory(const std::string& extension,
                                               OIIO::Filesystem::IOMemReader& memory,
                                               const OIIO::ImageSpec& config,
                                               const std::string& name) {
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

// `filePath` (may be ""): where the bytes came from, for formats OIIO reads only from files.
Texture decodeBytes(const std::vector<uint8_t>& bytes, std::string extension,
                    const std::string& name, const std::string& filePath) {
    if (bytes.empty()) throw InputError(name + ": image is empty");
    const std::string sniffed = sniffExtension(bytes, name);
    if (!sniffed.empty()) extension = sniffed;
    if (extension.empty()) throw InputError(name + ": not an image format we can decode");
    if (sniffed == "png") checkPngChunks(bytes, name);
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

// decodeBytes, with anything a library throws (bad_alloc on a lying header) as bad input.
Texture decodeGuarded(const std::vector<uint8_t>& bytes, const std::string& extension,
                      const std::string& name, const std::string& filePath) {
    try {
        return decodeBytes(bytes, extension, name, filePath);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(name + ": cannot decode: " + e.what());
    }
}

std::string mimeExtension(const std::string& mimeType) {
    if (mimeType == "image/png") return "png";
    if (mimeType == "image/jpeg") return "jpg";
    return "";
}

}  // namespace

Texture readTextureFile(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw InputError(path + ": image file not found");
    }
    std::ifstream in(path, std::ios::binary);
    const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                     std::istreambuf_iterator<char>()};
    if (!in && !in.eof()) throw InputError(path + ": cannot read image file");
    std::string extension = std::filesystem::path(path).extension().string();
    if (!extension.empty()) extension.erase(0, 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    Texture texture = decodeGuarded(bytes, extension, path, path);
    texture.name = std::filesystem::path(path).filename().string();
    texture.sourcePath = path;
    return texture;
}

Texture decodeTextureFromMemory(const std::vector<uint8_t>& bytes, const std::string& name,
                                const std::string& mimeType) {
    return decodeGuarded(bytes, mimeExtension(mimeType), name, "");
}

}  // namespace pt
