#pragma once
// glTF textures into Scene textures. Each glTF image is decoded once (by our OIIO reader,
// never tinygltf's); each distinct (image, wrapS, wrapT, magFilter) becomes one Scene
// texture. An image that is missing or cannot be decoded (KTX2, a broken PNG) adds ONE
// warning naming it, however many materials use it, and every slot using it falls back to
// its factors (texture -1). Internal to pt_assets.
#include <string>

#include "assets/gltf/gltf_context.h"
#include "render/kernel/material.h"

namespace pt {

constexpr const char* kWebpExtension = "EXT_texture_webp";

// Whether this build decodes WebP images (through OpenImageIO; without it, a texture's PNG or
// JPEG fallback is shown where it has one).
bool gltfWebpAvailable();

// A material's reference to a texture, from a core textureInfo or one inside an extension.
struct GltfTextureSlot {
    int index = -1;  // glTF texture; -1: the slot is empty
    int texCoord = 0;
    const tinygltf::Value* transform = nullptr;  // KHR_texture_transform object, if any
    std::string element;                         // e.g. "materials[2].normalTexture"
};

GltfTextureSlot gltfTextureSlot(const tinygltf::TextureInfo& info, std::string element);
GltfTextureSlot gltfTextureSlot(const tinygltf::NormalTextureInfo& info, std::string element);
// From an extension's textureInfo object (e.g. KHR_materials_transmission's).
GltfTextureSlot gltfTextureSlot(const tinygltf::Value& info, std::string element);

// The slot as a TextureRef with its KHR_texture_transform; texture -1 when the slot is
// empty or its image cannot be used.
TextureRef importGltfTexture(GltfContext& ctx, const GltfTextureSlot& slot);

}  // namespace pt
