#include "assets/image/image_write_oiio.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <functional>
#include <memory>

#include "assets/input_error.h"

namespace pt::oiio {
namespace {

// `writePixels` sends the pixels to the opened file; false when OIIO refused them.
void writeImage(const std::string& file, const std::string& path, OIIO::ImageSpec spec,
                const ImageMetadata& metadata, const std::function<bool(OIIO::ImageOutput&)>& writePixels) {
    for (const auto& [key, value] : metadata) spec.attribute(key, value);
    auto out = OIIO::ImageOutput::create(file);
    if (!out) throw InputError(path + ": no image writer for this extension: " + OIIO::geterror());
    if (!out->open(file, spec) || !writePixels(*out) || !out->close()) {
        throw InputError(path + ": cannot write image: " + out->geterror());
    }
}

OIIO::TypeDesc oiioType(ExrPixelType type) {
    switch (type) {
        case ExrPixelType::Half: return OIIO::TypeDesc::HALF;
        case ExrPixelType::Uint: return OIIO::TypeDesc::UINT32;
        default: return OIIO::TypeDesc::FLOAT;
    }
}

ExrPixelType exrType(OIIO::TypeDesc type, const std::string& path, const std::string& channel) {
    if (type == OIIO::TypeDesc::HALF) return ExrPixelType::Half;
    if (type == OIIO::TypeDesc::FLOAT) return ExrPixelType::Float;
    if (type == OIIO::TypeDesc::UINT32) return ExrPixelType::Uint;
    throw InputError(path + ": channel " + channel + " is " + type.c_str() +
                     ", not an EXR pixel type (half, float, uint)");
}

// One format for the whole image where the channels share it, else per-channel formats with
// float (the widest) as the default OIIO asks for.
OIIO::ImageSpec exrSpec(uint32_t width, uint32_t height, const std::vector<ExrChannelSource>& channels) {
    OIIO::ImageSpec spec(int(width), int(height), int(channels.size()), oiioType(channels[0].type));
    spec.channelnames.clear();
    spec.alpha_channel = -1;
    spec.z_channel = -1;
    bool mixed = false;
    for (const ExrChannelSource& c : channels) {
        if (c.name == "A") spec.alpha_channel = int(spec.channelnames.size());
        spec.channelnames.push_back(c.name);
        spec.channelformats.push_back(oiioType(c.type));
        mixed = mixed || c.type != channels[0].type;
    }
    if (mixed) {
        spec.format = OIIO::TypeDesc::FLOAT;
    } else {
        spec.channelformats.clear();
    }
    spec.attribute("compression", "zip");
    return spec;
}

// The largest finite half: half channels saturate here rather than overflow to infinity,
// which would poison every filter a compositor runs over them.
constexpr float kHalfMax = 65504.0f;

// Interleaves and sends the channels a band of rows at a time, so that memory stays a small
// multiple of one row whatever the number of layers.
bool writeChannelRows(OIIO::ImageOutput& out, uint32_t width, uint32_t height,
                      const std::vector<ExrChannelSource>& channels) {
    constexpr uint32_t kRowsPerBand = 32;
    const size_t n = channels.size();
    std::vector<float> band(size_t(width) * kRowsPerBand * n);
    for (uint32_t y0 = 0; y0 < height; y0 += kRowsPerBand) {
        const uint32_t y1 = std::min(height, y0 + kRowsPerBand);
        for (size_t p = size_t(y0) * width, i = 0; p < size_t(y1) * width; ++p, ++i) {
            for (size_t c = 0; c < n; ++c) {
                const float v = channels[c].values[p * channels[c].stride];
                band[i * n + c] =
                    channels[c].type == ExrPixelType::Half ? std::clamp(v, -kHalfMax, kHalfMax) : v;
            }
        }
        if (!out.write_scanlines(int(y0), int(y1), 0, OIIO::TypeDesc::FLOAT, band.data())) return false;
    }
    return true;
}

ImageMetadata stringAttributes(const OIIO::ImageSpec& spec) {
    ImageMetadata metadata;
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        metadata.emplace_back(p.name().string(), p.get_string());
    return metadata;
}

std::unique_ptr<OIIO::ImageInput> openForReading(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError(path + ": cannot read image: " + OIIO::geterror());
    return in;
}

std::vector<float> readAllChannels(OIIO::ImageInput& in, const std::string& path) {
    const OIIO::ImageSpec& spec = in.spec();
    std::vector<float> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
    if (!in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) {
        throw InputError(path + ": cannot decode image: " + in.geterror());
    }
    return pixels;
}

// Which channel fills R, G, B and A (-1: none; alpha is then 1).
std::array<int, 4> rgbaSources(const OIIO::ImageSpec& spec) {
    const std::array<int, 4> named = {spec.channelindex("R"), spec.channelindex("G"), spec.channelindex("B"),
                                      spec.channelindex("A")};
    if (named[0] >= 0 && named[1] >= 0 && named[2] >= 0) return named;
    const int n = spec.nchannels;
    if (n < 3) return {0, 0, 0, -1};
    return {0, 1, 2, n >= 4 ? 3 : -1};
}

}  // namespace

void writeExrChannels(const std::string& file, const std::string& path, uint32_t width, uint32_t height,
                      const std::vector<ExrChannelSource>& channels, const ImageMetadata& metadata) {
    if (channels.empty()) throw InputError(path + ": an EXR needs at least one channel");
    writeImage(file, path, exrSpec(width, height, channels), metadata,
               [&](OIIO::ImageOutput& out) { return writeChannelRows(out, width, height, channels); });
}

void writeDisplayImage(const std::string& file, const std::string& path, uint32_t width, uint32_t height,
                       const uint8_t* rgb, const ImageMetadata& metadata) {
    OIIO::ImageSpec spec(int(width), int(height), 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    writeImage(file, path, spec, metadata,
               [&](OIIO::ImageOutput& out) { return out.write_image(OIIO::TypeDesc::UINT8, rgb); });
}

std::vector<float> readImageRgba(const std::string& path, uint32_t& width, uint32_t& height) {
    auto in = openForReading(path);
    const OIIO::ImageSpec& spec = in->spec();
    width = uint32_t(spec.width);
    height = uint32_t(spec.height);
    const std::vector<float> pixels = readAllChannels(*in, path);
    const std::array<int, 4> source = rgbaSources(spec);
    const size_t n = size_t(spec.nchannels);
    std::vector<float> rgba(size_t(width) * height * 4, 1.0f);
    for (size_t i = 0; i < size_t(width) * height; ++i) {
        for (size_t c = 0; c < 4; ++c) {
            if (source[c] >= 0) rgba[i * 4 + c] = pixels[i * n + size_t(source[c])];
        }
    }
    return rgba;
}

ExrImage readExrChannels(const std::string& path) {
    auto in = openForReading(path);
    const OIIO::ImageSpec& spec = in->spec();
    const std::vector<float> pixels = readAllChannels(*in, path);
    ExrImage image;
    image.width = uint32_t(spec.width);
    image.height = uint32_t(spec.height);
    const size_t n = size_t(spec.nchannels), count = size_t(image.width) * image.height;
    for (size_t c = 0; c < n; ++c) {
        ExrChannelData channel;
        channel.name = spec.channel_name(int(c));
        channel.type = exrType(spec.channelformat(int(c)), path, channel.name);
        channel.values.resize(count);
        for (size_t i = 0; i < count; ++i) channel.values[i] = pixels[i * n + c];
        image.channels.push_back(std::move(channel));
    }
    image.metadata = stringAttributes(spec);
    return image;
}

ImageMetadata readImageMetadata(const std::string& path) {
    return stringAttributes(openForReading(path)->spec());
}

}  // namespace pt::oiio
