#include "render/backend/gl_pixel_buffer_link.h"

// Builds with CUDA and the GL headers define linkGlPixelBuffer in
// render/backend/cuda/cuda_gl_link.cpp.
#if !PT_HAVE_CUDA_GL
namespace pt {

std::unique_ptr<PixelBufferLink> linkGlPixelBuffer(uint32_t glBuffer, std::string& why) {
    (void)glBuffer;
#if PT_HAVE_CUDA
    why = "built without the OpenGL headers CUDA-GL interop needs";
#else
    why = "built without CUDA";
#endif
    return nullptr;
}

}  // namespace pt
#endif
