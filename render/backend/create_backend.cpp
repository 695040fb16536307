#include <stdexcept>

#include "render/backend/backend.h"
#include "render/backend/cpu/cpu_backend.h"

namespace pt {

std::unique_ptr<Backend> createBackend(const std::string& name) {
    if (name == "cpu") return std::make_unique<CpuBackend>();
    if (name == "cuda") {
        throw std::invalid_argument(
            "backend \"cuda\" is not available yet: this build has only the CPU backend (use --backend cpu)");
    }
    throw std::invalid_argument("unknown backend \"" + name + "\" (available: cpu)");
}

}  // namespace pt
