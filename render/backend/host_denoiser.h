#pragma once
// Backend::readDenoised on the host: the guides read back from a backend, then the CPU filter
// (render/denoise/). The read-back images and the filter's planes are kept for the next call,
// so a backend that denoises every frame (the editor's CPU backend) allocates them once.
#include <vector>

#include "render/backend/backend.h"
#include "render/denoise/denoiser.h"

namespace pt {

class HostDenoiser {
public:
    // The backend's beauty denoised into `rgba`; returns the filter's seconds.
    double run(const Backend& backend, std::vector<float>& rgba);

private:
    std::vector<float> beauty_, albedo_, normal_, depth_, emission_, alpha_, variance_;
    CpuDenoiser filter_;
};

}  // namespace pt
