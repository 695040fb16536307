#include "editor/ui/cuda_gl_frame.h"

#if defined(PT_HAVE_CUDA)
#include <cuda_gl_interop.h>
#include <cuda_runtime.h>
#endif

namespace pt::editor {

CudaGlFrame::~CudaGlFrame() { release(); }

void CudaGlFrame::release() {
#if defined(PT_HAVE_CUDA)
    if (resource_) cudaGraphicsUnregisterResource(resource_);
#endif
    resource_ = nullptr;
    if (pbo_) glDeleteBuffers(1, &pbo_);
    pbo_ = 0;
    width_ = height_ = 0;
}

bool CudaGlFrame::update(RenderWorker& worker, GLuint texture, uint32_t width, uint32_t height) {
#if defined(PT_HAVE_CUDA)
    if (failed_) return false;
    if (width != width_ || height != height_) {
        release();
        glGenBuffers(1, &pbo_);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo_);
        glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(size_t(width) * height * 4 * sizeof(float)), nullptr,
                     GL_STREAM_DRAW);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        if (cudaGraphicsGLRegisterBuffer(&resource_, pbo_, cudaGraphicsRegisterFlagsWriteDiscard) !=
            cudaSuccess) {
            cudaGetLastError();  // clear it: the renderer's own calls must not see it
            resource_ = nullptr;
            release();
            failed_ = true;
            why_ = "this OpenGL cannot share buffers with CUDA";
            return false;
        }
        width_ = width;
        height_ = height;
    }
    bool copied = false;
    worker.withBackend([&](EditorSession& session) {
        Backend& backend = session.backend();
        if (backend.width() != width || backend.height() != height) return;
        if (cudaGraphicsMapResources(1, &resource_) != cudaSuccess) return;
        void* device = nullptr;
        size_t bytes = 0;
        if (cudaGraphicsResourceGetMappedPointer(&device, &bytes, resource_) == cudaSuccess &&
            bytes >= size_t(width) * height * 4 * sizeof(float)) {
            copied = session.copyDisplayedToDevice(session.document().viewer.denoise, device);
        }
        cudaGraphicsUnmapResources(1, &resource_);
    });
    if (!copied) {
        cudaGetLastError();
        why_ = "the backend cannot write device frames";
        return false;
    }
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo_);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(width), GLsizei(height), GL_RGBA, GL_FLOAT, nullptr);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    why_ = "";
    return true;
#else
    (void)worker, (void)texture, (void)width, (void)height;
    why_ = "built without CUDA";
    return false;
#endif
}

}  // namespace pt::editor
