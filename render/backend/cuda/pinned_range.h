#pragma once
// PinnedRange: page-locks a range of host memory (cudaHostRegister) while it lives, so copies
// from it run at full bus speed instead of through the driver's pageable staging. The backend
// pins its host copy of the vertices, which every vertex edit uploads.
#include <cuda_runtime.h>

#include <cstddef>
#include <utility>

#include "render/backend/cuda/cuda_check.h"

namespace pt::cuda {

class PinnedRange {
public:
    PinnedRange(const void* data, size_t bytes) : data_(const_cast<void*>(data)) {
        if (data_ && bytes)
            PT_CUDA_CHECK(cudaHostRegister(data_, bytes, cudaHostRegisterDefault));
        else
            data_ = nullptr;
    }
    PinnedRange(const PinnedRange&) = delete;
    PinnedRange& operator=(const PinnedRange&) = delete;
    PinnedRange(PinnedRange&& other) noexcept : data_(std::exchange(other.data_, nullptr)) {}
    PinnedRange& operator=(PinnedRange&&) = delete;
    ~PinnedRange() {
        if (data_) cudaHostUnregister(data_);  // no throw from a destructor
    }

private:
    void* data_;
};

}  // namespace pt::cuda
