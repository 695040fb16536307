// linkGlPixelBuffer through CUDA-GL interop (render/backend/gl_pixel_buffer_link.h), where
// the GL headers cuda_gl_interop.h includes are present (render/CMakeLists.txt).
#if PT_HAVE_CUDA_GL
#include <cuda_gl_interop.h>
#include <cuda_runtime.h>

#include "render/backend/cuda/cuda_device.h"
#include "render/backend/gl_pixel_buffer_link.h"

namespace pt {
namespace {

class CudaGlLink final : public PixelBufferLink {
public:
    explicit CudaGlLink(cudaGraphicsResource* resource) : resource_(resource) {
        // Non-blocking: neither waits for nor holds up the renderer's stream (fill()).
        if (cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking) != cudaSuccess) failed();
    }
    ~CudaGlLink() override {
        unmap();
        cudaGraphicsUnregisterResource(resource_);
        if (stream_) cudaStreamDestroy(stream_);
    }
    CudaGlLink(const CudaGlLink&) = delete;
    CudaGlLink& operator=(const CudaGlLink&) = delete;

    void* map(size_t* bytes) override {
        if (!mapped_ && cudaGraphicsMapResources(1, &resource_, stream_) != cudaSuccess) return failed();
        mapped_ = true;
        void* device = nullptr;
        if (cudaGraphicsResourceGetMappedPointer(&device, bytes, resource_) != cudaSuccess) return failed();
        return device;
    }

    void unmap() override {
        if (mapped_) cudaGraphicsUnmapResources(1, &resource_, stream_);
        mapped_ = false;
    }

    bool fill(const void* deviceSource, size_t bytes) override {
        size_t size = 0;
        void* device = map(&size);
        const bool copied =
            device && size >= bytes &&
            cudaMemcpyAsync(device, deviceSource, bytes, cudaMemcpyDeviceToDevice, stream_) == cudaSuccess &&
            cudaStreamSynchronize(stream_) == cudaSuccess;
        if (!copied) failed();
        unmap();
        return copied;
    }

private:
    // Clears CUDA's sticky-until-read error, so the renderer's own calls do not see it.
    void* failed() {
        cudaGetLastError();
        return nullptr;
    }

    cudaGraphicsResource* resource_;
    cudaStream_t stream_ = nullptr;  // null (the legacy stream) where it could not be made
    bool mapped_ = false;
};

}  // namespace

std::unique_ptr<PixelBufferLink> linkGlPixelBuffer(uint32_t glBuffer, std::string& why) {
    if (!cuda::deviceAvailable(&why)) return nullptr;
    cudaGraphicsResource* resource = nullptr;
    if (cudaGraphicsGLRegisterBuffer(&resource, glBuffer, cudaGraphicsRegisterFlagsWriteDiscard) !=
        cudaSuccess) {
        cudaGetLastError();
        why = "this OpenGL cannot share buffers with CUDA";
        return nullptr;
    }
    return std::make_unique<CudaGlLink>(resource);
}

}  // namespace pt
#endif
