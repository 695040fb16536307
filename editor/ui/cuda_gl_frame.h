#pragma once
// CudaGlFrame: the CUDA backend's frames reach OpenGL without a host round trip. A pixel
// buffer object is registered with CUDA once per size; each frame the backend writes the mean
// image into it on the GPU (Backend::copyBeautyToDevice) and the texture is filled from it by
// the GL driver. Where registration fails (a GL that is not NVIDIA's, e.g. Mesa under Xvfb, or
// no CUDA at all) available() is false and the editor uploads host frames instead.
#include <cstdint>

#include "editor/render_worker.h"
#include "editor/ui/gl.h"

struct cudaGraphicsResource;

namespace pt::editor {

class CudaGlFrame {
public:
    CudaGlFrame() = default;
    ~CudaGlFrame();
    CudaGlFrame(const CudaGlFrame&) = delete;
    CudaGlFrame& operator=(const CudaGlFrame&) = delete;

    // Fills `texture` (RGBA32F, width x height) with the backend's beauty. False when interop
    // is unavailable for this backend or GL; the reason is kept in why().
    bool update(RenderWorker& worker, GLuint texture, uint32_t width, uint32_t height);
    const char* why() const { return why_; }

private:
    void release();
    GLuint pbo_ = 0;
    cudaGraphicsResource* resource_ = nullptr;
    uint32_t width_ = 0, height_ = 0;
    bool failed_ = false;
    const char* why_ = "not tried";
};

}  // namespace pt::editor
