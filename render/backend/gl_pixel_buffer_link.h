#pragma once
// The seam through which frames reach an OpenGL window without a host round trip: a pixel
// buffer object the window owns is linked to the GPU backend's device (CUDA-GL interop), and
// each frame the backend writes into it (Backend::copyBeautyToDevice, copyDenoisedToDevice)
// while it is mapped. The editor knows only this interface; the CUDA calls live in
// render/backend/cuda/. Where no link can be made (a build without CUDA or without the GL
// headers CUDA's interop needs, no GPU, a GL that is not NVIDIA's, e.g. Mesa under Xvfb)
// linkGlPixelBuffer says why and the window uploads host frames instead.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace pt {

class PixelBufferLink {
public:
    virtual ~PixelBufferLink() = default;  // unlinks the buffer (before GL deletes it)
    // Maps the buffer for the device: its device address, with its size in *bytes; null where
    // mapping fails. Between map() and unmap() GL must not touch the buffer.
    virtual void* map(size_t* bytes) = 0;
    virtual void unmap() = 0;
    // Copies `bytes` of device memory at `deviceSource` into the buffer (map, copy, unmap) on a
    // stream of its own, so that it never waits for the renderer's kernels in flight; false
    // where mapping fails or the buffer is smaller.
    virtual bool fill(const void* deviceSource, size_t bytes) = 0;
};

// Links GL buffer object `glBuffer` (current context; written by the device, its old contents
// discarded) to the GPU backends' device. Null with the reason in `why` where it cannot be.
std::unique_ptr<PixelBufferLink> linkGlPixelBuffer(uint32_t glBuffer, std::string& why);

}  // namespace pt
