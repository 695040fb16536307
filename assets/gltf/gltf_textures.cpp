#include "assets/gltf/gltf_textures.h"

#include <cmath>
#include <filesystem>

#include "assets/file_state.h"
#include "assets/gltf/gltf_accessors.h"
#include "assets/gltf/gltf_uri.h"
#include "assets/gltf/gltf_values.h"
#include "assets/image/image_read.h"

namespace pt {
namespace {

const tinygltf::Value* findTransform(const tinygltf::ExtensionMap& extensions) {
    auto it = extensions.find("KHR_texture_transform");
    return it == extensions.end() ? nullptr : &it->second;
}

WrapMode wrapMode(const GltfContext& ctx, int mode, const std::string& element) {
    switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return WrapMode::Repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return WrapMode::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return WrapMode::MirroredRepeat;
        default: ctx.fail(element, std::to_string(mode) + " is not a glTF wrap mode");
    }
}

std::string imageLabel(const tinygltf::Image& image, size_t index) {
    const std::string what = !image.name.empty()  ? image.name
                             : !image.uri.empty() ? decodeGltfUri(image.uri)
                                                  : std::string();
    return gltfPath("images", index) + (what.empty() ? "" : " '" + what + "'");
}

// The encoded bytes of an image, wherever the file keeps them.
std::vector<uint8_t> encodedImage(const GltfContext& ctx, const tinygltf::Image& image,
                                  const std::string& label) {
    if (image.as_is) return image.image;  // kept by keepEncodedImage (data URI or file)
    if (image.bufferView >= 0) return readGltfBufferView(ctx, image.bufferView, label);
    if (!image.uri.empty()) {
        // tinygltf could not read the file (or it was empty); it only warns, and so do we.
        const std::string path = (std::filesystem::path(ctx.doc.baseDir) / decodeGltfUri(image.uri)).string();
        const FileState state = fileState(path);
        throw InputError(ctx.doc.label + ": " + label + ": image " +
                         (state == FileState::Readable ? "file could not be read" : fileStateWords(state)));
    }
    throw InputError(ctx.doc.label + ": " + label + ": has neither bytes nor a file");
}

// The decoded image, or nullopt after ONE warning naming it (callers ask once per image).
std::optional<Texture> decodeImage(const GltfContext& ctx, int index, const std::string& element) {
    const auto& image = gltfElement(ctx, ctx.model().images, index, element, "image");
    const std::string label = imageLabel(image, size_t(index));
    try {
        Texture texture = decodeTextureFromMemory(encodedImage(ctx, image, label),
                                                  ctx.doc.label + ": " + label, image.mimeType);
        texture.name = image.name.empty() ? label : image.name;
        if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0) {
            texture.sourcePath = (std::filesystem::path(ctx.doc.baseDir) / decodeGltfUri(image.uri)).string();
        }
        return texture;
    } catch (const InputError& e) {
        ctx.scene.warnings.push_back(std::string(e.what()) +
                                     "; materials using it fall back to their factors");
        return std::nullopt;
    }
}

// Scene texture of image `source` under one sampler: decoded on the image's first use,
// copied from that first texture for another sampler; -1 when undecodable.
int32_t sceneTexture(GltfContext& ctx, int source, WrapMode wrapS, WrapMode wrapT, bool nearest,
                     const std::string& element) {
    const auto key = std::make_tuple(source, wrapS, wrapT, nearest);
    if (auto it = ctx.textures.find(key); it != ctx.textures.end()) return it->second;
    std::optional<Texture> texture;
    if (auto first = ctx.images.find(source); first == ctx.images.end()) {
        texture = decodeImage(ctx, source, element);
    } else if (first->second >= 0) {
        texture = ctx.scene.textures[size_t(first->second)];
    }
    int32_t index = -1;
    if (texture) {
        texture->wrapS = wrapS;
        texture->wrapT = wrapT;
        texture->nearest = nearest;
        texture->object = ctx.object;
        index = int32_t(ctx.scene.textures.size());
        ctx.scene.textures.push_back(std::move(*texture));
    }
    ctx.images.emplace(source, index);
    return ctx.textures[key] = index;
}

// KHR_texture_transform: offset, rotation (radians), scale, and a texCoord override.
void applyTransform(const GltfContext& ctx, const GltfTextureSlot& slot, TextureRef& ref, int& texCoord) {
    if (!slot.transform) return;
    const std::string element = slot.element + ".extensions.KHR_texture_transform";
    const auto offset = gltfNumbers(ctx, *slot.transform, "offset", {0.0, 0.0}, element);
    const auto scale = gltfNumbers(ctx, *slot.transform, "scale", {1.0, 1.0}, element);
    ref.offset = {float(offset[0]), float(offset[1])};
    ref.scale = {float(scale[0]), float(scale[1])};
    ref.rotation = float(gltfNumber(ctx, *slot.transform, "rotation", 0.0, element));
    const double set = gltfNumber(ctx, *slot.transform, "texCoord", texCoord, element);
    if (set < 0.0 || set > 255.0 || set != std::floor(set)) {
        ctx.fail(element + ".texCoord", "expected a texture coordinate set index");
    }
    texCoord = int(set);
}

// The image a texture shows: its EXT_texture_webp source where this build decodes WebP
// (OpenImageIO's WebP reader), else its PNG or JPEG one, else (no other) the WebP one anyway,
// whose decoding then warns; -1 where it has none.
int textureSource(const GltfContext& ctx, const tinygltf::Texture& texture, const std::string& element) {
    int webp = -1;
    if (auto it = texture.extensions.find(kWebpExtension); it != texture.extensions.end()) {
        const tinygltf::Value& source = it->second.Get("source");
        if (!source.IsInt()) ctx.fail(element + ".extensions." + kWebpExtension, "needs a source image");
        webp = source.GetNumberAsInt();
        gltfElement(ctx, ctx.model().images, webp, element + ".extensions." + kWebpExtension + ".source",
                    "image");
    }
    if (webp >= 0 && (gltfWebpAvailable() || texture.source < 0)) return webp;
    return texture.source;
}

}  // namespace

bool gltfWebpAvailable() { return PT_HAVE_OIIO != 0; }

GltfTextureSlot gltfTextureSlot(const tinygltf::TextureInfo& info, std::string element) {
    return {info.index, info.texCoord, findTransform(info.extensions), std::move(element)};
}

GltfTextureSlot gltfTextureSlot(const tinygltf::NormalTextureInfo& info, std::string element) {
    return {info.index, info.texCoord, findTransform(info.extensions), std::move(element)};
}

GltfTextureSlot gltfTextureSlot(const tinygltf::Value& info, std::string element) {
    GltfTextureSlot slot;
    slot.element = std::move(element);
    if (!info.IsObject()) return slot;
    // The index was checked against the textures by checkGltfJson.
    if (info.Has("index") && info.Get("index").IsInt()) {
        slot.index = info.Get("index").GetNumberAsInt();
    }
    if (info.Has("texCoord") && info.Get("texCoord").IsInt()) {
        slot.texCoord = info.Get("texCoord").GetNumberAsInt();
    }
    const tinygltf::Value& extensions = info.Get("extensions");
    if (extensions.IsObject() && extensions.Has("KHR_texture_transform")) {
        slot.transform = &extensions.Get("KHR_texture_transform");
    }
    return slot;
}

TextureRef importGltfTexture(GltfContext& ctx, const GltfTextureSlot& slot) {
    TextureRef ref;
    if (slot.index < 0) return ref;
    const std::string indexElement = slot.element + ".index";
    const auto& texture = gltfElement(ctx, ctx.model().textures, slot.index, indexElement, "texture");
    int texCoord = slot.texCoord;
    applyTransform(ctx, slot, ref, texCoord);
    if (texCoord != 0) {
        ctx.warn(slot.element, "uses TEXCOORD_" + std::to_string(texCoord) +
                                   "; only TEXCOORD_0 is imported, so the slot keeps its factor");
        return ref;
    }
    const std::string textureElement = gltfPath("textures", size_t(slot.index));
    const int source = textureSource(ctx, texture, textureElement);
    if (source < 0) {
        if (ctx.textureWarnings.insert(slot.index).second) {
            ctx.warn(textureElement,
                     "has no PNG or JPEG source image (only an extension's); "
                     "materials using it fall back to their factors");
        }
        return ref;
    }
    WrapMode wrapS = WrapMode::Repeat, wrapT = WrapMode::Repeat;
    bool nearest = false;
    if (texture.sampler >= 0) {
        const std::string samplerIndexElement = textureElement + ".sampler";
        const auto& sampler =
            gltfElement(ctx, ctx.model().samplers, texture.sampler, samplerIndexElement, "sampler");
        const std::string samplerElement = gltfPath("samplers", size_t(texture.sampler));
        wrapS = wrapMode(ctx, sampler.wrapS, samplerElement + ".wrapS");
        wrapT = wrapMode(ctx, sampler.wrapT, samplerElement + ".wrapT");
        if (sampler.magFilter != -1 && sampler.magFilter != TINYGLTF_TEXTURE_FILTER_NEAREST &&
            sampler.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR) {
            ctx.fail(samplerElement + ".magFilter",
                     std::to_string(sampler.magFilter) + " is not NEAREST or LINEAR");
        }
        nearest = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
    }
    ref.texture = sceneTexture(ctx, source, wrapS, wrapT, nearest, textureElement + ".source");
    return ref;
}

}  // namespace pt
