#pragma once
// Scene features: what a compiled scene uses, as a bit set (STYLE.md rule 7; Cycles' kernel
// features). The CUDA backend picks the kernel variant compiled for the smallest feature set
// that covers the scene's (render/backend/cuda/kernel_variants.h), so code a scene does not
// need is not in the kernel that runs. Shared per-ray code reads the compile-time set through
// hasFeature<kFeatures>(bit): `if constexpr` drops what a variant leaves out. The default,
// kAllFeatures, is the generic code the CPU backend and the tests run.
// This header is the bits alone, for per-ray code; scene_features.h adds the host functions.
#include <cstdint>

namespace pt {

// A set of features, one bit each (feature::k...).
using FeatureSet = uint64_t;

namespace feature {
// Texture slots sampled by some material.
constexpr FeatureSet kBaseColorTexture = FeatureSet{1} << 0;
constexpr FeatureSet kMetallicRoughnessTexture = FeatureSet{1} << 1;
constexpr FeatureSet kEmissiveTexture = FeatureSet{1} << 2;
constexpr FeatureSet kTransmissionTexture = FeatureSet{1} << 3;
constexpr FeatureSet kNormalMap = FeatureSet{1} << 4;
// Surfaces rays may pass: alpha MASK, alpha BLEND, culled back faces (doubleSided false).
constexpr FeatureSet kAlphaMask = FeatureSet{1} << 5;
constexpr FeatureSet kAlphaBlend = FeatureSet{1} << 6;
constexpr FeatureSet kBackfaceCulling = FeatureSet{1} << 7;
// Material lobes.
constexpr FeatureSet kSmoothTransmission = FeatureSet{1} << 8;
constexpr FeatureSet kRoughTransmission = FeatureSet{1} << 9;
constexpr FeatureSet kVolume = FeatureSet{1} << 10;  // KHR_materials_volume absorption
constexpr FeatureSet kClearcoat = FeatureSet{1} << 11;
constexpr FeatureSet kSpecularLayer = FeatureSet{1} << 12;  // KHR_materials_specular away from its defaults
constexpr FeatureSet kMetal = FeatureSet{1} << 13;
// Lights.
constexpr FeatureSet kEmissiveTriangles = FeatureSet{1} << 14;
constexpr FeatureSet kSphereLights = FeatureSet{1} << 15;
constexpr FeatureSet kPunctualLights = FeatureSet{1} << 16;
constexpr FeatureSet kConstantEnvironment = FeatureSet{1} << 17;  // a non-black constant colour
constexpr FeatureSet kImageEnvironment = FeatureSet{1} << 18;
// Camera, geometry, outputs.
constexpr FeatureSet kThinLens = FeatureSet{1} << 19;
constexpr FeatureSet kMorphTargets = FeatureSet{1} << 20;  // host-side only: weights refit BLASes
constexpr FeatureSet kMultipleInstances = FeatureSet{1}
                                          << 21;         // else the one instance's BLAS is walked alone
constexpr FeatureSet kSpheres = FeatureSet{1} << 22;     // analytic sphere primitives
constexpr FeatureSet kAovs = FeatureSet{1} << 23;        // AOVs asked for (set by the backend)
constexpr FeatureSet kBruteForce = FeatureSet{1} << 24;  // the "BVH off" toggle (set by the backend)
// A GGX reflection lobe that is not a mirror (rough metal, a rough dielectric specular layer):
// without it every reflection lobe is a delta lobe, and the GGX sampling and evaluation code of
// the specular lobe is left out.
constexpr FeatureSet kGlossyReflection = FeatureSet{1} << 25;
// KHR_materials_unlit surfaces: they end the path with their base colour.
constexpr FeatureSet kUnlit = FeatureSet{1} << 26;
// KHR_materials_diffuse_transmission: a Lambertian lobe into the other hemisphere.
constexpr FeatureSet kDiffuseTransmission = FeatureSet{1} << 27;
// KHR_materials_sheen: a Charlie fibre lobe over the rest (fabric, velvet).
constexpr FeatureSet kSheen = FeatureSet{1} << 28;
// KHR_materials_anisotropy: the GGX reflection and refraction lobes stretched along a direction.
constexpr FeatureSet kAnisotropy = FeatureSet{1} << 29;
// KHR_materials_iridescence: thin-film interference on the Fresnel term of the specular lobe.
constexpr FeatureSet kIridescence = FeatureSet{1} << 30;
// KHR_materials_dispersion: refraction whose index depends on the wavelength a path carries.
constexpr FeatureSet kDispersion = FeatureSet{1} << 31;
// Volumes whose interior scatters (KHR_materials_volume_scatter, subsurface): free flights,
// phase functions and light sampled from inside media (render/integrator/medium_scattering.h).
constexpr FeatureSet kScatteringMedia = FeatureSet{1} << 32;
// Index-matched volume boundaries (index 1, fully transmitting): rays and shadow rays pass them
// into and out of the volume they bound, as they would pass no surface (fog in a box).
constexpr FeatureSet kIndexMatchedBoundaries = FeatureSet{1} << 33;
constexpr uint32_t kCount = 34;  // of the 64 bits a FeatureSet holds

// Groups the kernels test.
constexpr FeatureSet kTextures =
    kBaseColorTexture | kMetallicRoughnessTexture | kEmissiveTexture | kTransmissionTexture;
constexpr FeatureSet kTransparency = kAlphaMask | kAlphaBlend | kBackfaceCulling;
constexpr FeatureSet kTransmission = kSmoothTransmission | kRoughTransmission;
// Lobes of glTF material extensions few scenes use: only the generic ("full") kernels carry
// them, so every other scene runs the code it ran before they were written.
constexpr FeatureSet kRareLobes = kDiffuseTransmission | kSheen | kAnisotropy | kIridescence | kDispersion |
                                  kScatteringMedia | kIndexMatchedBoundaries;
// Features no kernel code depends on: every variant has them. (AOVs select the generic
// kernels: recording them is a debugging and export path, not worth a variant of its own.)
constexpr FeatureSet kUngated =
    kSpecularLayer | kMetal | kEmissiveTriangles | kConstantEnvironment | kMorphTargets;
}  // namespace feature

constexpr FeatureSet kAllFeatures = (FeatureSet{1} << feature::kCount) - 1u;

// Whether code compiled for feature set kFeatures may meet `bits` (any of them).
template <FeatureSet kFeatures>
constexpr bool hasFeature(FeatureSet bits) {
    return (kFeatures & bits) != 0u;
}

}  // namespace pt
