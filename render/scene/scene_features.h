#pragma once
// Scene features: what a compiled scene uses, as a bit set (STYLE.md rule 7; Cycles' kernel
// features). The CUDA backend picks the kernel variant compiled for the smallest feature set
// that covers the scene's (render/backend/cuda/kernel_variants.h), so code a scene does not
// need is not in the kernel that runs. Shared per-ray code reads the compile-time set through
// hasFeature<kFeatures>(bit): `if constexpr` drops what a variant leaves out. The default,
// kAllFeatures, is the generic code the CPU backend and the tests run.
#include <cstdint>
#include <string>
#include <vector>

namespace pt {

struct CompiledScene;

namespace feature {
// Texture slots sampled by some material.
constexpr uint32_t kBaseColorTexture = 1u << 0;
constexpr uint32_t kMetallicRoughnessTexture = 1u << 1;
constexpr uint32_t kEmissiveTexture = 1u << 2;
constexpr uint32_t kTransmissionTexture = 1u << 3;
constexpr uint32_t kNormalMap = 1u << 4;
// Surfaces rays may pass: alpha MASK, alpha BLEND, culled back faces (doubleSided false).
constexpr uint32_t kAlphaMask = 1u << 5;
constexpr uint32_t kAlphaBlend = 1u << 6;
constexpr uint32_t kBackfaceCulling = 1u << 7;
// Material lobes.
constexpr uint32_t kSmoothTransmission = 1u << 8;
constexpr uint32_t kRoughTransmission = 1u << 9;
constexpr uint32_t kVolume = 1u << 10;  // KHR_materials_volume absorption
constexpr uint32_t kClearcoat = 1u << 11;
constexpr uint32_t kSpecularLayer = 1u << 12;  // KHR_materials_specular away from its defaults
constexpr uint32_t kMetal = 1u << 13;
// Lights.
constexpr uint32_t kEmissiveTriangles = 1u << 14;
constexpr uint32_t kSphereLights = 1u << 15;
constexpr uint32_t kPunctualLights = 1u << 16;
constexpr uint32_t kConstantEnvironment = 1u << 17;  // a non-black constant colour
constexpr uint32_t kImageEnvironment = 1u << 18;
// Camera, geometry, outputs.
constexpr uint32_t kThinLens = 1u << 19;
constexpr uint32_t kMorphTargets = 1u << 20;       // host-side only: weights refit BLASes
constexpr uint32_t kMultipleInstances = 1u << 21;  // else the one instance's BLAS is walked alone
constexpr uint32_t kSpheres = 1u << 22;            // analytic sphere primitives
constexpr uint32_t kAovs = 1u << 23;               // AOVs asked for (set by the backend)
constexpr uint32_t kBruteForce = 1u << 24;         // the "BVH off" toggle (set by the backend)
// A GGX reflection lobe that is not a mirror (rough metal, a rough dielectric specular layer):
// without it every reflection lobe is a delta lobe, and the GGX sampling and evaluation code of
// the specular lobe is left out.
constexpr uint32_t kGlossyReflection = 1u << 25;
// KHR_materials_unlit surfaces: they end the path with their base colour.
constexpr uint32_t kUnlit = 1u << 26;
// KHR_materials_diffuse_transmission: a Lambertian lobe into the other hemisphere.
constexpr uint32_t kDiffuseTransmission = 1u << 27;
// KHR_materials_sheen: a Charlie fibre lobe over the rest (fabric, velvet).
constexpr uint32_t kSheen = 1u << 28;
// KHR_materials_anisotropy: the GGX reflection and refraction lobes stretched along a direction.
constexpr uint32_t kAnisotropy = 1u << 29;
// KHR_materials_iridescence: thin-film interference on the Fresnel term of the specular lobe.
constexpr uint32_t kIridescence = 1u << 30;
// KHR_materials_dispersion: refraction whose index depends on the wavelength a path carries.
constexpr uint32_t kDispersion = 1u << 31;
// Every bit of the 32 is taken: the next feature widens the set to 64 bits.
constexpr uint32_t kCount = 32;

// Groups the kernels test.
constexpr uint32_t kTextures =
    kBaseColorTexture | kMetallicRoughnessTexture | kEmissiveTexture | kTransmissionTexture;
constexpr uint32_t kTransparency = kAlphaMask | kAlphaBlend | kBackfaceCulling;
constexpr uint32_t kTransmission = kSmoothTransmission | kRoughTransmission;
// Lobes of glTF material extensions few scenes use: only the generic ("full") kernels carry
// them, so every other scene runs the code it ran before they were written.
constexpr uint32_t kRareLobes = kDiffuseTransmission | kSheen | kAnisotropy | kIridescence | kDispersion;
// Features no kernel code depends on: every variant has them. (AOVs select the generic
// kernels: recording them is a debugging and export path, not worth a variant of its own.)
constexpr uint32_t kUngated =
    kSpecularLayer | kMetal | kEmissiveTriangles | kConstantEnvironment | kMorphTargets;
}  // namespace feature

constexpr uint32_t kAllFeatures = ~0u >> (32u - feature::kCount);

// Whether code compiled for feature set kFeatures may meet `bits` (any of them).
template <uint32_t kFeatures>
constexpr bool hasFeature(uint32_t bits) {
    return (kFeatures & bits) != 0u;
}

// The features of a compiled scene (everything but kAovs and kBruteForce, which the backend
// adds from its toggles and outputs). O(materials + lights): cheap enough after every edit.
uint32_t sceneFeatures(const CompiledScene& scene, bool morphTargets);

// Stable snake_case names, in bit order ("base_color_texture", ...), for info, stats JSON and
// the editor.
const char* featureName(uint32_t bit);
std::vector<std::string> featureNames(uint32_t features);
// "base_color_texture, normal_map, ..." or "none".
std::string describeFeatures(uint32_t features);

}  // namespace pt
