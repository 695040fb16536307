#include "editor/ui/interop_frame.h"

namespace pt::editor {

InteropFrame::~InteropFrame() { release(); }

void InteropFrame::release() {
    link_.reset();  // unlinked before GL deletes the buffer
    if (pbo_) glDeleteBuffers(1, &pbo_);
    pbo_ = 0;
    width_ = height_ = 0;
}

bool InteropFrame::copyFromBackend(RenderWorker& worker, uint32_t width, uint32_t height, size_t frameBytes) {
    bool copied = false;
    worker.withBackend([&](EditorSession& session) {
        Backend& backend = session.backend();
        if (!backend.capabilities().deviceFrames || backend.width() != width || backend.height() != height)
            return;
        size_t bytes = 0;
        void* device = link_->map(&bytes);
        if (device && bytes >= frameBytes)
            copied = session.copyDisplayedToDevice(session.document().viewer.denoise, device);
        link_->unmap();
    });
    return copied;
}

bool InteropFrame::update(RenderWorker& worker, GLuint texture, uint32_t width, uint32_t height) {
    if (failed_) return false;
    const size_t frameBytes = size_t(width) * height * 4 * sizeof(float);
    if (width != width_ || height != height_) {
        release();
        glGenBuffers(1, &pbo_);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo_);
        glBufferData(GL_PIXEL_UNPACK_BUFFER, GLsizeiptr(frameBytes), nullptr, GL_STREAM_DRAW);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        link_ = linkGlPixelBuffer(pbo_, why_);
        if (!link_) {
            release();
            failed_ = true;  // the reason stays in why_
            return false;
        }
        width_ = width;
        height_ = height;
    }
    // The render thread's copy of the frame, made as it was published; before there is one
    // (the first frame, or a frame of another size), the backend's own beauty, which waits for
    // the batch of passes in flight.
    bool copied = false;
    worker.withDeviceFrame([&](const void* rgba, uint32_t w, uint32_t h) {
        copied = w == width && h == height && link_->fill(rgba, frameBytes);
    });
    if (!copied) copied = copyFromBackend(worker, width, height, frameBytes);
    if (!copied) {
        why_ = "the backend cannot write device frames";
        return false;
    }
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pbo_);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, GLsizei(width), GLsizei(height), GL_RGBA, GL_FLOAT, nullptr);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    why_.clear();
    return true;
}

}  // namespace pt::editor
