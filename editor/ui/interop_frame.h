#pragma once
// InteropFrame: a GPU backend's frames reach OpenGL without a host round trip. A pixel buffer
// object is linked to the backend's device once per size (render/backend/gl_pixel_buffer_link.h);
// each frame the render thread's device copy of it (made as it was published:
// RenderWorker::withDeviceFrame) is copied into the buffer on the GPU, on a stream that does not
// wait for the passes in flight, and the texture is filled from it by the GL driver. Where no link can be
// made (a backend whose frames live on the host, a build without CUDA, a GL that is not NVIDIA's, e.g. Mesa
// under Xvfb) update() is false and the editor uploads host frames instead.
#include <cstdint>
#include <memory>

#include "editor/render_worker.h"
#include "editor/ui/gl.h"
#include "render/backend/gl_pixel_buffer_link.h"

namespace pt::editor {

class InteropFrame {
public:
    InteropFrame() = default;
    ~InteropFrame();
    InteropFrame(const InteropFrame&) = delete;
    InteropFrame& operator=(const InteropFrame&) = delete;

    // Fills `texture` (RGBA32F, width x height) with the backend's displayed image. False
    // when interop is unavailable for this backend or GL; the reason is kept in why().
    bool update(RenderWorker& worker, GLuint texture, uint32_t width, uint32_t height);
    const char* why() const { return why_.c_str(); }

private:
    void release();
    // The backend's beauty written into the buffer directly (waits for the passes in flight).
    bool copyFromBackend(RenderWorker& worker, uint32_t width, uint32_t height, size_t frameBytes);
    GLuint pbo_ = 0;
    std::unique_ptr<PixelBufferLink> link_;
    uint32_t width_ = 0, height_ = 0;
    bool failed_ = false;
    std::string why_ = "not tried";
};

}  // namespace pt::editor
