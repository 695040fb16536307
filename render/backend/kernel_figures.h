#pragma once
// What a GPU backend compiled, for `pt-render bench`: its kernel variants (specialised on scene
// features, render/backend/cuda/kernel_variants.h) and each kernel's resources as the module
// reports them. Empty where code is not compiled per variant (the CPU backend).
#include <cstddef>
#include <string>
#include <vector>

#include "render/kernel/feature_set.h"

namespace pt {

struct KernelVariantFigures {
    std::string name;
    FeatureSet features;  // what its kernels can render
};

// Resources of one compiled kernel.
struct KernelResources {
    std::string variant;  // a KernelVariantFigures name
    std::string kernel;   // "megakernel", "extend", "shade", "shadow"
    std::string symbol;   // the mangled name, to find it in a disassembly
    int registers = 0;
    size_t localBytes = 0;  // per thread: stack frame and spills
    size_t constantBytes = 0;
};

struct KernelFigures {
    std::vector<KernelVariantFigures> variants;
    std::vector<KernelResources> kernels;
};

}  // namespace pt
