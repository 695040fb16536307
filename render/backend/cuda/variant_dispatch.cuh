#pragma once
// forKernelVariant: calls fn(std::integral_constant<FeatureSet, features>) with the feature set
// of a kernel variant (kernel_variants.h) as a compile-time constant, so a launcher instantiates
// its kernel template once per variant and launches the one asked for.
#include <type_traits>

#include "render/backend/cuda/kernel_variants.h"

namespace pt::cuda {

template <uint32_t kIndex>
using VariantFeatures = std::integral_constant<FeatureSet, kKernelVariants[kIndex].features>;

template <class Fn>
void forKernelVariant(uint32_t variant, Fn&& fn) {
    static_assert(kKernelVariantCount == 7, "one case per kernel variant");
    switch (variant) {
        case 0: fn(VariantFeatures<0>{}); return;
        case 1: fn(VariantFeatures<1>{}); return;
        case 2: fn(VariantFeatures<2>{}); return;
        case 3: fn(VariantFeatures<3>{}); return;
        case 4: fn(VariantFeatures<4>{}); return;
        case 5: fn(VariantFeatures<5>{}); return;
        default: fn(VariantFeatures<kFullVariant>{}); return;
    }
}

}  // namespace pt::cuda
