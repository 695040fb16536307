#include "assets/image_write_oiio.h"

#include <OpenImageIO/imageio.h>

#include "assets/input_error.h"

namespace pt {
namespace {

void writeWithOiio(const std::string& file, const std::string& path, OIIO::ImageSpec spec,
                   OIIO::TypeDesc pixelType, const void* pixels, const ImageMetadata& metadata) {
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    auto out = OIIO::ImageOutput::create(file);
    if (!out) throw InputError(path + ": no image writer for this extension: " + OIIO::geterror());
    if (!out->open(file, spec) || !out->write_image(pixelType, pixels) || !out->close()) {
        throw InputError(path + ": cannot write image: " + out->geterror());
    }
}

}  // namespace

void writeExrWithOiio(const std::string& file, const std::string& path, uint32_t width,
                      uint32_t height, const float* rgba, const ImageMetadata& metadata) {
    OIIO::ImageSpec spec(int(width), int(height), 4, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    writeWithOiio(file, path, spec, OIIO::TypeDesc::FLOAT, rgba, metadata);
}

void writeDisplayImageWithOiio(const std::string& file, const std::string& path, uint32_t width,
                               uint32_t height, const uint8_t* rgb, const ImageMetadata& metadata) {
    OIIO::ImageSpec spec(int(width), int(height), 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    writeWithOiio(file, path, spec, OIIO::TypeDesc::UINT8, rgb, metadata);
}

std::vector<float> readImageRgbaWithOiio(const std::string& path, uint32_t& width, uint32_t& height) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError(path + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    width = uint32_t(spec.width);
    height = uint32_t(spec.height);
    const int channels = spec.nchannels;
    std::vector<float> pixels(size_t(width) * height * size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
        throw InputError(path + ": cannot decode image: " + in->geterror());
    }
    std::vector<float> rgba(size_t(width) * height * 4, 1.0f);
    for (size_t i = 0; i < size_t(width) * height; ++i) {
        for (int c = 0; c < 4 && c < channels; ++c) rgba[i * 4 + size_t(c)] = pixels[i * size_t(channels) + size_t(c)];
        if (channels < 3) rgba[i * 4 + 1] = rgba[i * 4 + 2] = rgba[i * 4];
    }
    return rgba;
}

}  // namespace pt
