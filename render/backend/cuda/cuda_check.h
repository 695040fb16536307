#pragma once
// Every CUDA runtime call goes through PT_CUDA_CHECK, and every kernel launch is followed by
// PT_CUDA_CHECK_LAUNCH: a failure throws std::runtime_error naming the call, the file and line,
// and CUDA's own message, instead of surfacing later as a wrong image.
#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

namespace pt::cuda {

// The source file as the project names it (render/backend/cuda/...): __FILE__ holds the path
// of the tree the binary was built in, which means nothing to a user and should not reach them.
inline std::string projectSourceName(const char* file) {
    const std::string path(file);
    const size_t render = path.rfind("/render/");
    return render != std::string::npos ? path.substr(render + 1) : path.substr(path.rfind('/') + 1);
}

[[noreturn]] inline void throwCudaError(cudaError_t error, const char* what, const char* file, int line) {
    throw std::runtime_error(std::string("CUDA error in ") + what + " (" + projectSourceName(file) + ":" +
                             std::to_string(line) + "): " + cudaGetErrorName(error) + ": " +
                             cudaGetErrorString(error));
}

}  // namespace pt::cuda

#define PT_CUDA_CHECK(call)                                                      \
    do {                                                                         \
        const cudaError_t ptCudaError_ = (call);                                 \
        if (ptCudaError_ != cudaSuccess)                                         \
            ::pt::cuda::throwCudaError(ptCudaError_, #call, __FILE__, __LINE__); \
    } while (0)

// After a <<<...>>> launch: launch-configuration errors show up here, not at the launch.
#define PT_CUDA_CHECK_LAUNCH(kernelName)                                              \
    do {                                                                              \
        const cudaError_t ptCudaError_ = cudaGetLastError();                          \
        if (ptCudaError_ != cudaSuccess)                                              \
            ::pt::cuda::throwCudaError(ptCudaError_, kernelName, __FILE__, __LINE__); \
    } while (0)
