#include "render/backend/cuda/cuda_device.h"

#include <cuda_runtime.h>

#include "render/backend/cuda/cuda_check.h"

namespace pt::cuda {

bool deviceAvailable(std::string* why) {
    int count = 0;
    const cudaError_t error = cudaGetDeviceCount(&count);
    if (error != cudaSuccess) {
        if (why)
            *why = std::string("no usable CUDA device (") + cudaGetErrorName(error) + ": " +
                   cudaGetErrorString(error) + ")";
        cudaGetLastError();  // clear the sticky-free error so later checks start clean
        return false;
    }
    if (count == 0) {
        if (why) *why = "no CUDA device found";
        return false;
    }
    return true;
}

DeviceInfo deviceInfo() {
    std::string why;
    if (!deviceAvailable(&why)) throw std::runtime_error(why);
    cudaDeviceProp props{};
    PT_CUDA_CHECK(cudaGetDeviceProperties(&props, 0));
    DeviceInfo info;
    info.name = props.name;
    info.computeMajor = props.major;
    info.computeMinor = props.minor;
    info.multiprocessors = props.multiProcessorCount;
    info.memoryBytes = props.totalGlobalMem;
    return info;
}

}  // namespace pt::cuda
