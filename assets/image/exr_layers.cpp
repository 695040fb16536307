#include "assets/image/exr_layers.h"

#include "assets/atomic_file.h"
#include "assets/image/image_metadata.h"
#include "assets/image/image_read_format.h"
#include "assets/input_error.h"
#if PT_HAVE_OIIO
#include "assets/image/oiio_image_io.h"
#endif

namespace pt {
namespace {

// The channel names after "<aov>." (exr_layers.h gives the reasons).
std::vector<std::string> channelSuffixes(Aov aov) {
    switch (aov) {
        case Aov::Albedo:
        case Aov::Emission: return {"R", "G", "B"};
        case Aov::ShadingNormal:
        case Aov::GeometricNormal:
        case Aov::Position: return {"X", "Y", "Z"};
        case Aov::Depth: return {"Z"};
        case Aov::Uv: return {"U", "V"};
        case Aov::BvhCost: return {"nodes", "primitives"};
        case Aov::Alpha: return {"A"};
        default: return {"Y"};
    }
}

std::string validAovNames() { return aovListText(kAllAovs, ", ") + " (or all)"; }

AovMask parseOneAov(const std::string& name, const std::string& list) {
    if (name == "all") return kAllAovs;
    Aov aov;
    if (name.empty()) throw InputError("empty AOV name in \"" + list + "\"; valid names: " + validAovNames());
    if (!parseAov(name, aov))
        throw InputError("unknown AOV \"" + name + "\"; valid names: " + validAovNames());
    return aovBit(aov);
}

}  // namespace

std::vector<ExrChannelSource> interleavedChannels(const std::vector<std::string>& names, ExrPixelType type,
                                                  const float* pixels, size_t stride) {
    std::vector<ExrChannelSource> channels;
    for (size_t i = 0; i < names.size(); ++i) channels.push_back({names[i], type, pixels + i, stride});
    return channels;
}

std::vector<std::string> aovExrChannelNames(Aov aov) {
    std::vector<std::string> names;
    for (const std::string& suffix : channelSuffixes(aov))
        names.push_back(std::string(aovName(aov)) + "." + suffix);
    return names;
}

ExrPixelType aovExrPixelType(Aov aov, ExrPixelType precision) {
    switch (aov) {
        case Aov::InstanceId:
        case Aov::MaterialId:
        case Aov::SampleCount:
        case Aov::Depth:
        case Aov::Position: return ExrPixelType::Float;
        default: return precision;
    }
}

void writeExrChannels(const std::string& path, uint32_t width, uint32_t height,
                      const std::vector<ExrChannelSource>& channels, const ImageMetadata& metadata) {
#if PT_HAVE_OIIO
    writeFileAtomically(path, [&](const std::string& temp) {
        oiioImageIo().writeExrChannels(temp, path, width, height, channels, metadata);
    });
#else
    (void)width, (void)height, (void)channels, (void)metadata;
    throw InputError(needsOpenImageIoMessage(path, "exr"));
#endif
}

void writeLayeredExr(const std::string& path, const LayeredExr& image) {
    const uint32_t w = image.width, h = image.height;
    if (image.precision == ExrPixelType::Uint) throw InputError(path + ": an EXR render is half or float");
    checkPixelCount(path, w, h, 4, image.beauty.size());
    std::vector<ExrChannelSource> channels =
        interleavedChannels({"R", "G", "B", "A"}, image.precision, image.beauty.data(), 4);
    AovMask written = 0;
    for (const AovImage& layer : image.aovs) {
        const std::string name = aovName(layer.aov);
        if (uint32_t(layer.aov) >= kAovCount) throw InputError(path + ": no such AOV");
        if (written & aovBit(layer.aov)) throw InputError(path + ": AOV " + name + " given twice");
        written |= aovBit(layer.aov);
        checkPixelCount(path + ": AOV " + name, w, h, 4, layer.rgba.size());
        const std::vector<ExrChannelSource> more = interleavedChannels(
            aovExrChannelNames(layer.aov), aovExrPixelType(layer.aov, image.precision), layer.rgba.data(), 4);
        channels.insert(channels.end(), more.begin(), more.end());
    }
    if (!image.denoised.empty()) {
        checkPixelCount(path + ": the denoised layer", w, h, 4, image.denoised.size());
        const std::vector<ExrChannelSource> more = interleavedChannels(
            {"denoised.R", "denoised.G", "denoised.B"}, image.precision, image.denoised.data(), 4);
        channels.insert(channels.end(), more.begin(), more.end());
    }
    ImageMetadata metadata = image.metadata;
    metadata.emplace_back("pt:aovs", aovListText(written));
    writeExrChannels(path, w, h, channels, metadata);
}

LayeredExr layeredExr(RenderedImages images, ExrPixelType precision, const Camera& camera,
                      ImageMetadata metadata) {
    LayeredExr exr{images.width,
                   images.height,
                   std::move(images.beauty),
                   std::move(images.aovs),
                   precision,
                   std::move(metadata),
                   {}};
    const ImageMetadata view = cameraMetadata(camera, exr.width, exr.height);
    exr.metadata.insert(exr.metadata.end(), view.begin(), view.end());
    return exr;
}

AovMask parseAovList(const std::string& list) {
    AovMask mask = 0;
    size_t start = 0;
    for (;;) {
        const size_t comma = list.find(',', start);
        mask |= parseOneAov(list.substr(start, comma - start), list);
        if (comma == std::string::npos) return mask;
        start = comma + 1;
    }
}

std::string aovListText(AovMask mask, const std::string& separator) {
    std::string text;
    for (uint32_t i = 0; i < kAovCount; ++i) {
        if (mask & aovBit(Aov(i))) text += (text.empty() ? "" : separator) + aovName(Aov(i));
    }
    return text;
}

const ExrChannelData* ExrImage::channel(const std::string& name) const {
    for (const ExrChannelData& c : channels) {
        if (c.name == name) return &c;
    }
    return nullptr;
}

std::string ExrImage::attribute(const std::string& key) const {
    for (const auto& [k, value] : metadata) {
        if (k == key) return value;
    }
    return "";
}

ExrImage readExrChannels(const std::string& path) {
#if PT_HAVE_OIIO
    return oiioImageIo().readExrChannels(path);
#else
    throw InputError(needsOpenImageIoMessage(path, "exr"));
#endif
}

}  // namespace pt
