#pragma once
// MTL materials, as tinyobjloader parsed them, into Scene materials. What maps to what:
//   Kd -> baseColor; metallic 0; Ns -> roughness = sqrt(2 / (Ns + 2)) clamped to [0, 1]
//   (the Blinn-Phong exponent to GGX-roughness equivalence of Walter et al. 2007);
//   Ke -> emission (strength 1); Ni -> ior when Ni > 1 (exporters write "Ni 1" as a
//   placeholder for opaque materials, which would erase their specular reflection);
//   d, or 1 - Tr -> alpha, and alpha < 1 -> AlphaMode::Blend;
//   illum 4, 6, 7, 9 (the MTL models with transparency: glass, refraction) -> transmission 1,
//   tinted by Tf when Tf is given; illum 5 (Fresnel mirror, no transparency) -> metallic 1
//   colored by Ks; map_Kd -> baseColorTexture, map_Ke -> emissiveTexture, with -o / -s
//   options as the texture transform and -clamp as clamp-to-edge.
// Other MTL fields (Ka, Ks for illum 2, bump, map_d, the PBR extension) are not imported.
// A texture file that is missing or cannot be decoded adds one warning naming it, and the
// slot falls back to its factor. Internal to pt_assets.
#include <tiny_obj_loader.h>

#include <cstdint>
#include <map>
#include <string>

#include "assets/obj/obj_text_check.h"
#include "render/scene/scene.h"

namespace pt {

struct ObjMaterialContext {
    std::string label;  // the OBJ's file name, for messages
    std::string dir;    // texture paths are relative to it
    int32_t object = -1;
    Scene& scene;
    const ObjTextFacts& facts;
    std::map<std::string, int32_t> textures;  // resolved path -> Scene texture (-1: failed)
};

uint32_t importObjMaterial(ObjMaterialContext& ctx, const tinyobj::material_t& mtl);

// The material for faces without usemtl (Material's defaults), named "OBJ default".
uint32_t importObjDefaultMaterial(ObjMaterialContext& ctx);

}  // namespace pt
