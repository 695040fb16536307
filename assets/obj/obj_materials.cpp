#include "assets/obj/obj_materials.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "assets/image/image_read.h"
#include "assets/input_error.h"

namespace pt {
namespace {

// A color keyword, honouring the one-number gray shorthand tinyobjloader misreads.
Vec3 color(const ObjMaterialContext& ctx, const tinyobj::material_t& mtl, const char* keyword,
           const float (&rgb)[3]) {
    auto it = ctx.facts.grayColors.find({mtl.name, keyword});
    if (it != ctx.facts.grayColors.end()) return Vec3(it->second);
    return {rgb[0], rgb[1], rgb[2]};
}

Vec3 clamp01(Vec3 c) { return {clampf(c.x, 0.0f, 1.0f), clampf(c.y, 0.0f, 1.0f), clampf(c.z, 0.0f, 1.0f)}; }

// OBJ texture coordinates have v up from the image's bottom; the importer stores
// v' = 1 - v (glTF's convention, top-left origin). An MTL transform t = s * uv + o in OBJ
// space becomes, in the flipped space, scale s and offset (o_u, 1 - s_v - o_v).
void applyOptions(const tinyobj::texture_option_t& options, TextureRef& ref) {
    ref.scale = {options.scale[0], options.scale[1]};
    ref.offset = {options.origin_offset[0], 1.0f - options.scale[1] - options.origin_offset[1]};
}

int32_t importTexture(ObjMaterialContext& ctx, const std::string& name,
                      const tinyobj::texture_option_t& options, const std::string& material) {
    std::string relative = name;
    std::replace(relative.begin(), relative.end(), '\\', '/');  // written on Windows
    const std::string path = (std::filesystem::path(ctx.dir) / relative).lexically_normal().string();
    const std::string key = path + (options.clamp ? "#clamp" : "");
    if (auto it = ctx.textures.find(key); it != ctx.textures.end()) return it->second;
    int32_t index = -1;
    try {
        Texture texture = readTextureFile(path);
        if (options.clamp) texture.wrapS = texture.wrapT = WrapMode::ClampToEdge;
        texture.object = ctx.object;
        index = int32_t(ctx.scene.textures.size());
        ctx.scene.textures.push_back(std::move(texture));
    } catch (const InputError& e) {
        ctx.scene.warnings.push_back(ctx.label + ": material '" + material + "': texture '" + name +
                                     "': " + e.what() + "; the material uses its color");
    }
    return ctx.textures[key] = index;
}

}  // namespace

uint32_t importObjMaterial(ObjMaterialContext& ctx, const tinyobj::material_t& mtl) {
    Material m;
    m.baseColor = clamp01(color(ctx, mtl, "Kd", mtl.diffuse));
    m.metallic = 0.0f;
    // Walter et al. 2007: a Blinn-Phong exponent Ns matches GGX roughness sqrt(2 / (Ns + 2)).
    m.roughness = clampf(std::sqrt(2.0f / (std::max(mtl.shininess, 0.0f) + 2.0f)), 0.0f, 1.0f);
    const Vec3 emission = color(ctx, mtl, "Ke", mtl.emission);
    m.emission = vmax(emission, Vec3(0.0f));
    if (mtl.ior > 1.0f) m.ior = mtl.ior;
    m.alpha = clampf(mtl.dissolve, 0.0f, 1.0f);
    if (m.alpha < 1.0f) m.alphaMode = AlphaMode::Blend;
    if (mtl.illum == 4 || mtl.illum == 6 || mtl.illum == 7 || mtl.illum == 9) {
        m.transmission = 1.0f;
        const Vec3 filter = color(ctx, mtl, "Tf", mtl.transmittance);
        if (!isBlack(filter)) m.baseColor = clamp01(filter);  // glTF tints transmission by baseColor
    } else if (mtl.illum == 5) {
        const Vec3 ks = clamp01({mtl.specular[0], mtl.specular[1], mtl.specular[2]});
        m.metallic = 1.0f;
        if (!isBlack(ks)) m.baseColor = ks;
    }
    if (!mtl.diffuse_texname.empty()) {
        m.baseColorTexture.texture = importTexture(ctx, mtl.diffuse_texname, mtl.diffuse_texopt, mtl.name);
        applyOptions(mtl.diffuse_texopt, m.baseColorTexture);
    }
    if (!mtl.emissive_texname.empty()) {
        m.emissiveTexture.texture = importTexture(ctx, mtl.emissive_texname, mtl.emissive_texopt, mtl.name);
        applyOptions(mtl.emissive_texopt, m.emissiveTexture);
        // MTL multiplies map_Ke by Ke; a texture with Ke 0 would never glow, so it means 1.
        if (m.emissiveTexture.present() && isBlack(m.emission)) m.emission = Vec3(1.0f);
    }
    const uint32_t index = uint32_t(ctx.scene.materials.size());
    ctx.scene.materials.push_back({mtl.name, m, ctx.object});
    return index;
}

uint32_t importObjDefaultMaterial(ObjMaterialContext& ctx) {
    const uint32_t index = uint32_t(ctx.scene.materials.size());
    ctx.scene.materials.push_back({"OBJ default", Material(), ctx.object});
    return index;
}

}  // namespace pt
