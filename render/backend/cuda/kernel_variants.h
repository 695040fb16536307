#pragma once
// The feature sets the CUDA kernels are compiled for (feature_set.h; Cycles' kernel
// features). Each variant is the megakernel and the wavefront stages instantiated with its set
// as a compile-time constant, so code a scene does not need is not in the kernel that runs.
// A scene runs the first variant, from the leanest, whose set covers the scene's; "full", the
// generic code, covers every scene. Precompiling a few sets (rather than compiling one per
// scene at run time with NVRTC) keeps the first frame of any scene free of compilation, and
// the build time of the CUDA code within a few variants' worth; the sets are chosen from the
// scenes users bring: a Cornell-style box (diffuse, mirrors, smooth glass, area lights), the
// same with glossy and rough materials, each also as one instance (a scanned or generated
// mesh: its BLAS is walked without a TLAS), the glossy ones also with base-colour and
// metallic-roughness textures, and a textured glTF with normal maps and alpha under an HDR sky. The GGX code
// of rough lobes is the largest part of the shading code (a third of the "lean" megakernel's
// instructions, measured with nvdisasm line info), so "lean" leaves it out.
#include <cstdint>
#include <string>
#include <vector>

#include "render/backend/kernel_figures.h"
#include "render/kernel/feature_set.h"

namespace pt::cuda {

struct KernelVariant {
    const char* name;
    FeatureSet features;  // what its kernels can render
};

namespace variant_features {
using namespace feature;
// Untextured diffuse, mirrors and smooth glass, culled back faces, every light but the image
// environment.
constexpr FeatureSet kLeanSingle =
    kUngated | kSmoothTransmission | kBackfaceCulling | kSpheres | kSphereLights | kPunctualLights;
constexpr FeatureSet kLean = kLeanSingle | kMultipleInstances;
// Rough metals, specular layers and glass on top, and the two texture slots glTF materials use
// most (base colour, metallic-roughness): all texture lookups call one out-of-line sampler
// (texture_sample.h), so a slot adds a call, not a copy of the sampler.
constexpr FeatureSet kGlossySingle =
    kLeanSingle | kGlossyReflection | kRoughTransmission | kBaseColorTexture | kMetallicRoughnessTexture;
constexpr FeatureSet kGlossy = kGlossySingle | kMultipleInstances;
// What glTF scenes usually bring on top: textures, normal maps, alpha, an HDR sky, depth of field,
// unlit (baked or stylised) materials.
constexpr FeatureSet kTextured =
    kGlossy | kTextures | kNormalMap | kTransparency | kImageEnvironment | kThinLens | kUnlit;
// Everything but the rare lobes (clearcoat, volumes, every texture slot, ...) and the debugging
// paths (AOVs, brute force): adding a rare lobe to "full" slowed a clearcoat golf ball by 5%
// before this variant kept it out.
constexpr FeatureSet kLayered = kAllFeatures & ~(kRareLobes | kAovs | kBruteForce);
}  // namespace variant_features

inline constexpr KernelVariant kKernelVariants[] = {
    {"lean-single", variant_features::kLeanSingle},
    {"lean", variant_features::kLean},
    {"glossy-single", variant_features::kGlossySingle},
    {"glossy", variant_features::kGlossy},
    {"textured", variant_features::kTextured},
    {"layered", variant_features::kLayered},
    {"full", kAllFeatures},
};
constexpr uint32_t kKernelVariantCount = sizeof(kKernelVariants) / sizeof(kKernelVariants[0]);
constexpr uint32_t kFullVariant = kKernelVariantCount - 1;

constexpr bool variantCovers(uint32_t variant, FeatureSet features) {
    return (features & ~kKernelVariants[variant].features) == 0u;
}

// The variant that renders `features`: `requested` (an index, or -1 for none) where it covers
// them, else the leanest that does (always found: the last covers all).
constexpr uint32_t chooseKernelVariant(FeatureSet features, int requested = -1) {
    if (requested >= 0 && uint32_t(requested) < kKernelVariantCount &&
        variantCovers(uint32_t(requested), features)) {
        return uint32_t(requested);
    }
    for (uint32_t i = 0; i < kKernelVariantCount; ++i) {
        if (variantCovers(i, features)) return i;
    }
    return kFullVariant;
}

// The index of the variant named `name`; -1 for "" or an unknown name.
inline int kernelVariantIndex(const std::string& name) {
    for (uint32_t i = 0; i < kKernelVariantCount; ++i) {
        if (name == kKernelVariants[i].name) return int(i);
    }
    return -1;
}

// Each kernel's resources, read from the module (cudaFuncGetAttributes).
std::vector<KernelResources> kernelResources();

}  // namespace pt::cuda
