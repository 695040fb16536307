#include "render/compile/scene_features.h"

#include "render/compile/compile_scene.h"
#include "render/integrator/medium.h"
#include "render/materials/alpha.h"
#include "render/materials/ggx.h"

namespace pt {

namespace {

FeatureSet materialFeatures(const Material& m) {
    using namespace feature;
    FeatureSet f = 0;
    if (m.baseColorTexture.present()) f |= kBaseColorTexture;
    if (m.unlit) {  // its base colour and alpha are all that is read of it
        f |= kUnlit;
        if (materialMayBeTransparent(m)) f |= m.alphaMode == AlphaMode::Mask ? kAlphaMask : kAlphaBlend;
        if (cullsBackFaces(m)) f |= kBackfaceCulling;
        return f;
    }
    if (m.metallicRoughnessTexture.present()) f |= kMetallicRoughnessTexture;
    if (m.emissiveTexture.present() && m.isEmissive()) f |= kEmissiveTexture;
    if (m.transmissionTexture.present()) f |= kTransmissionTexture;
    if (m.normalTexture.present()) f |= kNormalMap;
    if (materialMayBeTransparent(m)) f |= m.alphaMode == AlphaMode::Mask ? kAlphaMask : kAlphaBlend;
    if (cullsBackFaces(m)) f |= kBackfaceCulling;
    if (m.metallic > 0.0f) f |= kMetal;  // a texture only scales the factor
    // The reflection lobe has weight (metal or a specular layer) and a roughness the texture can
    // only scale down: smooth factors stay mirrors.
    if ((m.metallic > 0.0f || m.specular > 0.0f) && !ggxIsSmooth(ggxAlpha(m.roughness)))
        f |= kGlossyReflection;
    // Subsurface scattering enters its medium through the glass lobe (material_eval.h).
    const bool mayTransmit =
        (m.transmission > 0.0f || m.transmissionTexture.present() || m.subsurface > 0.0f) &&
        m.metallic < 1.0f;
    if (mayTransmit) {
        const bool smooth = ggxIsSmooth(ggxAlpha(m.roughness));
        f |= smooth ? kSmoothTransmission : kRoughTransmission;
        // A roughness texture can scale any roughness down to smooth.
        if (m.metallicRoughnessTexture.present()) f |= kSmoothTransmission;
    }
    if ((mayTransmit || m.diffuseTransmission > 0.0f) && isVolumeBoundary(m)) {
        const HomogeneousMedium medium = mediumOf(m);
        if (maxComponent(medium.sigmaT) > 0.0f) f |= kVolume;
        if (medium.scatters()) f |= kScatteringMedia;
        if (m.subsurface > 0.0f) f |= kScatteringMedia;  // its BSDF mixes subsurface in, whatever the medium
        if (isIndexMatchedBoundary(m)) f |= kIndexMatchedBoundaries | kVolume;
    }
    if (m.clearcoat > 0.0f) f |= kClearcoat;
    if (m.diffuseTransmission > 0.0f && m.metallic < 1.0f) f |= kDiffuseTransmission;
    if (maxComponent(m.sheenColor) > 0.0f) f |= kSheen;  // a black factor disables the layer
    if (m.anisotropyStrength > 0.0f && (m.metallic > 0.0f || m.specular > 0.0f || mayTransmit))
        f |= kAnisotropy;
    if (m.iridescence > 0.0f && (m.metallic > 0.0f || m.specular > 0.0f)) f |= kIridescence;
    if (m.dispersion > 0.0f && mayTransmit) f |= kDispersion;
    if (m.specular != 1.0f || m.specularColor.x != 1.0f || m.specularColor.y != 1.0f ||
        m.specularColor.z != 1.0f) {
        f |= kSpecularLayer;
    }
    return f;
}

}  // namespace

FeatureSet sceneFeatures(const CompiledScene& scene, bool morphTargets) {
    using namespace feature;
    FeatureSet f = 0;
    // Only materials some traced instance uses: a library of unused materials costs nothing.
    std::vector<bool> used(scene.materials.size(), false);
    for (const uint32_t m : scene.instanceMaterials) {
        if (m < used.size() && !used[m]) {
            used[m] = true;
            f |= materialFeatures(scene.materials[m]);
        }
    }
    if (scene.stats.emitterCount > 0) f |= kEmissiveTriangles;
    if (scene.stats.sphereLightCount > 0) f |= kSphereLights;
    if (!scene.punctualLights.empty()) f |= kPunctualLights;
    if (scene.environment.texture >= 0) {
        f |= kImageEnvironment;
    } else if (maxComponent(scene.environment.color) > 0.0f) {
        f |= kConstantEnvironment;
    }
    if (scene.camera.lensRadius > 0.0f) f |= kThinLens;
    if (morphTargets) f |= kMorphTargets;
    if (scene.instances.size() > 1) f |= kMultipleInstances;
    if (!scene.spheres.empty()) f |= kSpheres;
    if (scene.bruteForce) f |= kBruteForce;
    return f;
}

const char* featureName(FeatureSet bit) {
    static const char* const kNames[feature::kCount] = {"base_color_texture",
                                                        "metallic_roughness_texture",
                                                        "emissive_texture",
                                                        "transmission_texture",
                                                        "normal_map",
                                                        "alpha_mask",
                                                        "alpha_blend",
                                                        "backface_culling",
                                                        "smooth_transmission",
                                                        "rough_transmission",
                                                        "volume",
                                                        "clearcoat",
                                                        "specular_layer",
                                                        "metal",
                                                        "emissive_triangles",
                                                        "sphere_lights",
                                                        "punctual_lights",
                                                        "constant_environment",
                                                        "image_environment",
                                                        "thin_lens",
                                                        "morph_targets",
                                                        "multiple_instances",
                                                        "spheres",
                                                        "aovs",
                                                        "brute_force",
                                                        "glossy_reflection",
                                                        "unlit",
                                                        "diffuse_transmission",
                                                        "sheen",
                                                        "anisotropy",
                                                        "iridescence",
                                                        "dispersion",
                                                        "scattering_media",
                                                        "index_matched_boundaries"};
    for (uint32_t i = 0; i < feature::kCount; ++i) {
        if (bit == (FeatureSet{1} << i)) return kNames[i];
    }
    return "unknown";
}

std::vector<std::string> featureNames(FeatureSet features) {
    std::vector<std::string> names;
    for (uint32_t i = 0; i < feature::kCount; ++i) {
        if (features & (FeatureSet{1} << i)) names.push_back(featureName(FeatureSet{1} << i));
    }
    return names;
}

std::string describeFeatures(FeatureSet features) {
    std::string s;
    for (const std::string& name : featureNames(features)) s += (s.empty() ? "" : ", ") + name;
    return s.empty() ? "none" : s;
}

}  // namespace pt
