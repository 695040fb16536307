#pragma once
// Whether this process can use a CUDA GPU, and which one: the question every GPU test and
// createBackend("cuda") asks first, so that machines without a GPU get a clear message.
#include <cstdint>
#include <string>

namespace pt::cuda {

struct DeviceInfo {
    std::string name;  // e.g. "NVIDIA H100 80GB HBM3"
    int computeMajor = 0, computeMinor = 0;
    int multiprocessors = 0;
    uint64_t memoryBytes = 0;
};

// True when a CUDA device can be used; otherwise false with the reason in `why` (no driver,
// no device, ...). Never throws.
bool deviceAvailable(std::string* why = nullptr);

// Device 0. Throws std::runtime_error when deviceAvailable() is false.
DeviceInfo deviceInfo();

}  // namespace pt::cuda
