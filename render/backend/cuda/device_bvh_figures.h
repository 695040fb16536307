#pragma once
// CudaBackend::measureDeviceBvh's work: the device BVH builders (gpu_bvh.h) timed with stream
// events on copies of the input, leaving the backend's scene alone.
#include <cuda_runtime.h>

#include "render/backend/device_bvh_figures.h"

namespace pt::cuda {

DeviceBvhFigures measureDeviceBvhBuilds(const BvhBuildInput& input, uint32_t runs, cudaStream_t stream);

}  // namespace pt::cuda
