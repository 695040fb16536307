#include <stdexcept>

#include "render/backend/backend.h"
#include "render/backend/cpu/cpu_backend.h"
#if PT_HAVE_CUDA
#include "render/backend/cuda/cuda_backend.h"
#include "render/backend/cuda/cuda_device.h"
#endif

namespace pt {

std::unique_ptr<Backend> createBackend(const std::string& name) {
    if (name == "cpu") return std::make_unique<CpuBackend>();
#if PT_HAVE_CUDA
    if (name == "cuda") {
        try {
            return std::make_unique<cuda::CudaBackend>();
        } catch (const std::runtime_error& e) {
            throw std::invalid_argument(std::string(e.what()) + " (use --backend cpu)");
        }
    }
    throw std::invalid_argument("unknown backend \"" + name + "\" (available: cpu, cuda)");
#else
    if (name == "cuda") {
        throw std::invalid_argument(
            "backend \"cuda\" is not in this build: it was configured without nvcc (PT_CUDA=OFF); use "
            "--backend cpu");
    }
    throw std::invalid_argument("unknown backend \"" + name + "\" (available: cpu)");
#endif
}

std::string defaultBackendName() {
#if PT_HAVE_CUDA
    if (cuda::deviceAvailable()) return "cuda";
#endif
    return "cpu";
}

}  // namespace pt
