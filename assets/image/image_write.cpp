#include "assets/image/image_write.h"

#include <fstream>

#include "assets/atomic_file.h"
#include "assets/image/exr_layers.h"
#include "assets/image/image_read_format.h"
#include "assets/image/pfm_file.h"
#include "assets/input_error.h"
#if PT_HAVE_OIIO
#include "assets/image/oiio_image_io.h"
#else
#include "assets/image/image_read.h"
#include "assets/image/image_write_stb.h"
#endif

namespace pt {
namespace {

#if !PT_HAVE_OIIO
void writeBytesAtomically(const std::string& path, const std::vector<uint8_t>& bytes) {
    writeFileAtomically(path, [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        out.close();
        if (!out) throw InputError(path + ": cannot write image");
    });
}
#endif

}  // namespace

ImageMetadata renderMetadata(uint32_t spp, const std::string& renderSeconds, const std::string& backend,
                             const std::string& scene, const std::string& software) {
    return {{"pt:spp", std::to_string(spp)},
            {"pt:render_seconds", renderSeconds},
            {"pt:backend", backend},
            {"pt:scene", scene},
            {"Software", software}};
}

void writeExr(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba,
              const ImageMetadata& metadata) {
    checkPixelCount(path, width, height, 4, rgba.size());
    writeExrChannels(path, width, height,
                     interleavedChannels({"R", "G", "B", "A"}, ExrPixelType::Float, rgba.data(), 4),
                     metadata);
}

void writeDisplayImage(const std::string& path, uint32_t width, uint32_t height,
                       const std::vector<uint8_t>& rgb, const ImageMetadata& metadata) {
    checkPixelCount(path, width, height, 3, rgb.size());
#if PT_HAVE_OIIO
    writeFileAtomically(path, [&](const std::string& temp) {
        oiioImageIo().writeDisplayImage(temp, path, width, height, rgb.data(), metadata);
    });
#else
    const std::string extension = lowercaseExtension(path);
    if (extension == "png") {
        writeBytesAtomically(path, encodePngWithStb(path, width, height, rgb, metadata));
    } else if (extension == "jpg" || extension == "jpeg") {
        writeBytesAtomically(path, encodeJpegWithStb(path, width, height, rgb));
    } else if (extension == "tif" || extension == "tiff" || extension == "exr") {
        throw InputError(needsOpenImageIoMessage(path, extension));
    } else {
        throw InputError(path +
                         ": no image writer for this extension (this build, without "
                         "OpenImageIO, writes .png and .jpg)");
    }
#endif
}

std::vector<float> readImageRgba(const std::string& path, uint32_t& width, uint32_t& height) {
    if (isPfmPath(path)) return readPfm(path, width, height);  // the same exact floats in every build
#if PT_HAVE_OIIO
    return oiioImageIo().readImageRgba(path, width, height);
#else
    // Through the texture reader: alpha stays straight (OIIO premultiplies it here) and 16-bit
    // PNGs come back rounded to 8 bits.
    const Texture texture = readTextureFile(path);
    width = texture.width;
    height = texture.height;
    if (texture.format == TexelFormat::RGBA32F) return texture.texelsF;
    std::vector<float> rgba(texture.texels8.size());
    for (size_t i = 0; i < rgba.size(); ++i) rgba[i] = float(texture.texels8[i]) * (1.0f / 255.0f);
    return rgba;
#endif
}

}  // namespace pt
