// kernelResources(): registers, local memory and constant memory of each variant's kernels, as
// the module holds them, for pt-render bench and the notes on kernel size.
#include "render/backend/cuda/cuda_check.h"
#include "render/backend/cuda/kernel_variants.h"
#include "render/backend/cuda/wavefront_kernels.h"

namespace pt::cuda {

namespace {

KernelResources resourcesOf(const char* variant, const char* kernel, const void* symbol) {
    KernelResources r;
    r.variant = variant;
    r.kernel = kernel;
    cudaFuncAttributes attributes{};
    PT_CUDA_CHECK(cudaFuncGetAttributes(&attributes, symbol));
    r.registers = attributes.numRegs;
    r.localBytes = attributes.localSizeBytes;
    r.constantBytes = attributes.constSizeBytes;
    const char* name = nullptr;
    if (cudaFuncGetName(&name, symbol) == cudaSuccess && name) r.symbol = name;
    return r;
}

}  // namespace

std::vector<KernelResources> kernelResources() {
    std::vector<KernelResources> all;
    for (uint32_t v = 0; v < kKernelVariantCount; ++v) {
        const char* name = kKernelVariants[v].name;
        const WavefrontSymbols w = wavefrontSymbols(v);
        all.push_back(resourcesOf(name, "megakernel", megakernelSymbol(v)));
        all.push_back(resourcesOf(name, "extend", w.extend));
        all.push_back(resourcesOf(name, "shade", w.shade));
        all.push_back(resourcesOf(name, "shadow", w.shadow));
    }
    return all;
}

}  // namespace pt::cuda
