#pragma once
// glTF materials into Scene materials, once each: metallic-roughness factors and textures,
// normal (+scale) and emissive textures, alpha mode and cutoff, doubleSided, and the
// extensions the renderer models (KHR_materials_emissive_strength, _ior, _transmission
// (+texture), _volume, _clearcoat factors, _specular factors; KHR_texture_transform on every
// slot). Values the file leaves out take glTF's defaults (metallic 1, roughness 1, single
// sided, ...), not Material's. Occlusion textures and extension textures other than
// transmissionTexture are not imported. Internal to pt_assets.
#include <string>

#include "assets/gltf/gltf_context.h"

namespace pt {

// Scene::materials index of glTF material `material` (-1: the spec's default material, added
// once per file). `element` names the referrer for messages.
uint32_t importGltfMaterial(GltfContext& ctx, int material, const std::string& element);

}  // namespace pt
