#include "assets/gltf/gltf_materials.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "assets/gltf/gltf_textures.h"
#include "assets/gltf/gltf_values.h"

namespace pt {
namespace {

// glTF 2.0's defaults for everything a material may leave out (Material's own defaults are
// an artist's, see material.h).
Material gltfDefaultMaterial() {
    Material m;
    m.baseColor = Vec3(1.0f);
    m.alpha = 1.0f;
    m.metallic = 1.0f;
    m.roughness = 1.0f;
    m.emission = Vec3(0.0f);
    m.emissionStrength = 1.0f;
    m.ior = 1.5f;
    m.transmission = 0.0f;
    m.specular = 1.0f;
    m.specularColor = Vec3(1.0f);
    m.clearcoat = 0.0f;
    m.clearcoatRoughness = 0.0f;
    m.thickness = 0.0f;
    m.attenuationColor = Vec3(1.0f);
    m.attenuationDistance = kInf;
    m.alphaMode = AlphaMode::Opaque;
    m.alphaCutoff = 0.5f;
    m.normalScale = 1.0f;
    m.doubleSided = 0;
    return m;
}

float unit(double v) { return float(std::clamp(v, 0.0, 1.0)); }
Vec3 unit3(const std::vector<double>& v) { return {unit(v[0]), unit(v[1]), unit(v[2])}; }

const tinygltf::Value* extension(const tinygltf::Material& material, const char* name) {
    auto it = material.extensions.find(name);
    return it == material.extensions.end() ? nullptr : &it->second;
}

// A number of an extension object that the extension bounds to [lo, hi]: a value outside is
// clamped with one warning naming it (a non-finite one is an error, as for every number).
float boundedNumber(GltfContext& ctx, const tinygltf::Value& object, const char* key, double fallback,
                    double lo, double hi, const std::string& element) {
    const double v = gltfNumber(ctx, object, key, fallback, element);
    if (v >= lo && v <= hi) return float(v);
    const double bound = v < lo ? lo : hi;
    char text[96];
    std::snprintf(text, sizeof text, "%g is %s %g; %g used", v, v < lo ? "below" : "above", bound, bound);
    ctx.warn(element + "." + key, text);
    return float(bound);
}

// The texture slot `key` of a material extension's object, where it has one.
TextureRef extensionTexture(GltfContext& ctx, const tinygltf::Value& extensionObject, const char* key,
                            const std::string& where) {
    if (!extensionObject.IsObject() || !extensionObject.Has(key)) return {};
    return importGltfTexture(ctx, gltfTextureSlot(extensionObject.Get(key), where + "." + key));
}

void readCore(GltfContext& ctx, const tinygltf::Material& src, const std::string& element, Material& m) {
    const auto& pbr = src.pbrMetallicRoughness;
    const std::string pbrElement = element + ".pbrMetallicRoughness";
    checkGltfNumbers(ctx, pbr.baseColorFactor, 4, pbrElement + ".baseColorFactor");
    checkGltfNumbers(ctx, {pbr.metallicFactor, pbr.roughnessFactor}, 2, pbrElement);
    checkGltfNumbers(ctx, src.emissiveFactor, 3, element + ".emissiveFactor");
    checkGltfNumbers(ctx, {src.alphaCutoff, src.normalTexture.scale}, 2, element);
    m.baseColor = unit3(pbr.baseColorFactor);
    m.alpha = unit(pbr.baseColorFactor[3]);
    m.metallic = unit(pbr.metallicFactor);
    m.roughness = unit(pbr.roughnessFactor);
    m.emission = unit3(src.emissiveFactor);
    m.alphaCutoff = float(std::max(src.alphaCutoff, 0.0));
    m.normalScale = float(src.normalTexture.scale);
    m.doubleSided = src.doubleSided ? 1u : 0u;
    if (src.alphaMode == "OPAQUE" || src.alphaMode.empty())
        m.alphaMode = AlphaMode::Opaque;
    else if (src.alphaMode == "MASK")
        m.alphaMode = AlphaMode::Mask;
    else if (src.alphaMode == "BLEND")
        m.alphaMode = AlphaMode::Blend;
    else
        ctx.fail(element + ".alphaMode", "'" + src.alphaMode + "' is not OPAQUE, MASK or BLEND");

    m.baseColorTexture =
        importGltfTexture(ctx, gltfTextureSlot(pbr.baseColorTexture, pbrElement + ".baseColorTexture"));
    m.metallicRoughnessTexture = importGltfTexture(
        ctx, gltfTextureSlot(pbr.metallicRoughnessTexture, pbrElement + ".metallicRoughnessTexture"));
    m.normalTexture = importGltfTexture(ctx, gltfTextureSlot(src.normalTexture, element + ".normalTexture"));
    m.emissiveTexture =
        importGltfTexture(ctx, gltfTextureSlot(src.emissiveTexture, element + ".emissiveTexture"));
}

// KHR_materials_anisotropy, _iridescence and _dispersion, with the extensions' defaults.
void readAnisotropyIridescenceDispersion(GltfContext& ctx, const tinygltf::Material& src,
                                         const std::string& base, Material& m) {
    constexpr double kMax = double(FLT_MAX);
    if (const auto* e = extension(src, "KHR_materials_anisotropy")) {
        const std::string where = base + "KHR_materials_anisotropy";
        m.anisotropyStrength = boundedNumber(ctx, *e, "anisotropyStrength", 0.0, 0.0, 1.0, where);
        // Any angle: radians, counter-clockwise in tangent space.
        m.anisotropyRotation = float(gltfNumber(ctx, *e, "anisotropyRotation", 0.0, where));
        m.anisotropyTexture = extensionTexture(ctx, *e, "anisotropyTexture", where);
    }
    if (const auto* e = extension(src, "KHR_materials_iridescence")) {
        const std::string where = base + "KHR_materials_iridescence";
        m.iridescence = boundedNumber(ctx, *e, "iridescenceFactor", 0.0, 0.0, 1.0, where);
        m.iridescenceIor = boundedNumber(ctx, *e, "iridescenceIor", 1.3, 1.0, kMax, where);
        m.iridescenceThicknessMin =
            boundedNumber(ctx, *e, "iridescenceThicknessMinimum", 100.0, 0.0, kMax, where);
        m.iridescenceThicknessMax =
            boundedNumber(ctx, *e, "iridescenceThicknessMaximum", 400.0, 0.0, kMax, where);
        m.iridescenceTexture = extensionTexture(ctx, *e, "iridescenceTexture", where);
        m.iridescenceThicknessTexture = extensionTexture(ctx, *e, "iridescenceThicknessTexture", where);
    }
    if (const auto* e = extension(src, "KHR_materials_dispersion")) {
        m.dispersion =
            boundedNumber(ctx, *e, "dispersion", 0.0, 0.0, kMax, base + "KHR_materials_dispersion");
    }
}

// The KHR_materials_volume_scatter proposal (glTF pull request 2453): the volume's interior
// scatters. Its drafts name the colour multiscatterColor and, later, multiscatterColorFactor.
void readVolumeScatter(GltfContext& ctx, const tinygltf::Material& src, const std::string& base,
                       Material& m) {
    const auto* e = extension(src, "KHR_materials_volume_scatter");
    if (!e) return;
    const std::string where = base + "KHR_materials_volume_scatter";
    const char* colorKey =
        e->Has("multiscatterColorFactor") ? "multiscatterColorFactor" : "multiscatterColor";
    m.scatterColor = unit3(gltfNumbers(ctx, *e, colorKey, {0, 0, 0}, where));
    m.scatterAnisotropy = boundedNumber(ctx, *e, "scatterAnisotropy", 0.0, -1.0, 1.0, where);
    if (e->Has("multiscatterColorTexture"))
        ctx.warn(where, "multiscatterColorTexture is not supported; the factor alone is used");
}

void readExtensions(GltfContext& ctx, const tinygltf::Material& src, const std::string& element,
                    Material& m) {
    const std::string base = element + ".extensions.";
    if (const auto* e = extension(src, "KHR_materials_emissive_strength")) {
        m.emissionStrength = float(std::max(
            gltfNumber(ctx, *e, "emissiveStrength", 1.0, base + "KHR_materials_emissive_strength"), 0.0));
    }
    if (const auto* e = extension(src, "KHR_materials_ior")) {
        // The extension allows ior 0 ("infinite", for metals); a dielectric below 1 is not
        // physical either, so both become the smallest meaningful value, 1.
        m.ior = float(std::max(gltfNumber(ctx, *e, "ior", 1.5, base + "KHR_materials_ior"), 1.0));
    }
    if (const auto* e = extension(src, "KHR_materials_transmission")) {
        const std::string where = base + "KHR_materials_transmission";
        m.transmission = unit(gltfNumber(ctx, *e, "transmissionFactor", 0.0, where));
        m.transmissionTexture = extensionTexture(ctx, *e, "transmissionTexture", where);
    }
    if (const auto* e = extension(src, "KHR_materials_volume")) {
        const std::string where = base + "KHR_materials_volume";
        m.thickness = float(std::max(gltfNumber(ctx, *e, "thicknessFactor", 0.0, where), 0.0));
        m.attenuationColor = unit3(gltfNumbers(ctx, *e, "attenuationColor", {1, 1, 1}, where));
        const double distance = gltfNumber(ctx, *e, "attenuationDistance", kInf, where);
        m.attenuationDistance = distance > 0.0 ? float(distance) : kInf;
    }
    if (const auto* e = extension(src, "KHR_materials_clearcoat")) {
        const std::string where = base + "KHR_materials_clearcoat";
        m.clearcoat = unit(gltfNumber(ctx, *e, "clearcoatFactor", 0.0, where));
        m.clearcoatRoughness = unit(gltfNumber(ctx, *e, "clearcoatRoughnessFactor", 0.0, where));
    }
    if (const auto* e = extension(src, "KHR_materials_diffuse_transmission")) {
        const std::string where = base + "KHR_materials_diffuse_transmission";
        m.diffuseTransmission = unit(gltfNumber(ctx, *e, "diffuseTransmissionFactor", 0.0, where));
        m.diffuseTransmissionColor =
            unit3(gltfNumbers(ctx, *e, "diffuseTransmissionColorFactor", {1, 1, 1}, where));
        m.diffuseTransmissionTexture = extensionTexture(ctx, *e, "diffuseTransmissionTexture", where);
        m.diffuseTransmissionColorTexture =
            extensionTexture(ctx, *e, "diffuseTransmissionColorTexture", where);
    }
    if (const auto* e = extension(src, "KHR_materials_sheen")) {
        const std::string where = base + "KHR_materials_sheen";
        m.sheenColor = unit3(gltfNumbers(ctx, *e, "sheenColorFactor", {0, 0, 0}, where));
        m.sheenRoughness = unit(gltfNumber(ctx, *e, "sheenRoughnessFactor", 0.0, where));
        m.sheenColorTexture = extensionTexture(ctx, *e, "sheenColorTexture", where);
        m.sheenRoughnessTexture = extensionTexture(ctx, *e, "sheenRoughnessTexture", where);
    }
    readAnisotropyIridescenceDispersion(ctx, src, base, m);
    readVolumeScatter(ctx, src, base, m);
    // KHR_materials_unlit: an empty object; its presence is the whole of it.
    if (extension(src, "KHR_materials_unlit")) m.unlit = 1;
    if (const auto* e = extension(src, "KHR_materials_specular")) {
        const std::string where = base + "KHR_materials_specular";
        m.specular = unit(gltfNumber(ctx, *e, "specularFactor", 1.0, where));
        const auto color = gltfNumbers(ctx, *e, "specularColorFactor", {1, 1, 1}, where);
        // The extension lets specularColorFactor exceed 1; only negatives are meaningless.
        m.specularColor = {float(std::max(color[0], 0.0)), float(std::max(color[1], 0.0)),
                           float(std::max(color[2], 0.0))};
    }
}

}  // namespace

uint32_t importGltfMaterial(GltfContext& ctx, int index, const std::string& element) {
    if (auto it = ctx.materials.find(index); it != ctx.materials.end()) return it->second;
    NamedMaterial named;
    named.object = ctx.object;
    named.params = gltfDefaultMaterial();
    if (index < 0) {
        named.name = "glTF default";
    } else {
        const auto& src = gltfElement(ctx, ctx.model().materials, index, element, "material");
        const std::string materialElement = gltfPath("materials", size_t(index));
        named.name = src.name.empty() ? materialElement : src.name;
        readCore(ctx, src, materialElement, named.params);
        readExtensions(ctx, src, materialElement, named.params);
    }
    const uint32_t sceneIndex = uint32_t(ctx.scene.materials.size());
    ctx.scene.materials.push_back(std::move(named));
    ctx.materials[index] = sceneIndex;
    return sceneIndex;
}

}  // namespace pt
