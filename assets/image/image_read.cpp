#include "assets/image/image_read.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "assets/image/image_read_format.h"
#include "assets/image/image_read_stb.h"
#include "assets/input_error.h"
#if PT_HAVE_OIIO
#include "assets/image/oiio_image_io.h"
#endif

namespace pt {
namespace {

// `filePath` (may be ""): where the bytes came from, for formats OIIO reads only from files.
Texture decodeBytes(const std::vector<uint8_t>& bytes, std::string extension, const std::string& name,
                    [[maybe_unused]] const std::string& filePath) {
    if (bytes.empty()) throw InputError(name + ": image is empty");
    // Readers are picked by extension; memory has none, and the bytes outrank a file's name.
    const std::string sniffed = sniffImageExtension(bytes, name);
    if (!sniffed.empty()) extension = sniffed;
    if (extension.empty()) throw InputError(name + ": not an image format we can decode");
    if (sniffed == "png") checkPngChunks(bytes, name);
#if PT_HAVE_OIIO
    return oiioImageIo().decodeTexture(bytes, extension, name, filePath);
#else
    if (!stbDecodesExtension(extension)) {
        throw InputError(needsOpenImageIoMessage(name, extension));
    }
    return decodeTextureWithStb(bytes, name);
#endif
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
    if (mimeType == "image/webp") return "webp";
    return "";
}

}  // namespace

Texture readTextureFile(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw InputError(path + ": image file not found");
    }
    std::ifstream in(path, std::ios::binary);
    const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in && !in.eof()) throw InputError(path + ": cannot read image file");
    Texture texture = decodeGuarded(bytes, lowercaseExtension(path), path, path);
    texture.name = std::filesystem::path(path).filename().string();
    texture.sourcePath = path;
    return texture;
}

Texture decodeTextureFromMemory(const std::vector<uint8_t>& bytes, const std::string& name,
                                const std::string& mimeType) {
    return decodeGuarded(bytes, mimeExtension(mimeType), name, "");
}

}  // namespace pt
