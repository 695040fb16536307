#pragma once
// StreamTimer: GPU time of work queued on a stream, from a pair of CUDA events (what the
// launches took on the device, without the host's launch overhead or later copies).
#include <cuda_runtime.h>

#include <utility>

#include "render/backend/cuda/cuda_check.h"

namespace pt::cuda {

class StreamTimer {
public:
    StreamTimer() {
        PT_CUDA_CHECK(cudaEventCreate(&begin_));
        PT_CUDA_CHECK(cudaEventCreate(&end_));
    }
    ~StreamTimer() {
        cudaEventDestroy(begin_);
        cudaEventDestroy(end_);
    }
    StreamTimer(const StreamTimer&) = delete;
    StreamTimer& operator=(const StreamTimer&) = delete;

    // Seconds the GPU spent on what `queue` puts on `stream`; waits for it to finish.
    template <class Queue>
    double time(cudaStream_t stream, Queue&& queue) {
        PT_CUDA_CHECK(cudaEventRecord(begin_, stream));
        std::forward<Queue>(queue)();
        PT_CUDA_CHECK(cudaEventRecord(end_, stream));
        PT_CUDA_CHECK(cudaEventSynchronize(end_));
        float ms = 0.0f;
        PT_CUDA_CHECK(cudaEventElapsedTime(&ms, begin_, end_));
        return double(ms) * 1e-3;
    }

private:
    cudaEvent_t begin_ = nullptr, end_ = nullptr;
};

}  // namespace pt::cuda
