#pragma once
// OpenImageIO's readers and writers, loaded on first use. OpenImageIO brings about 260 shared
// libraries with it; linked into the programs, the dynamic loader spent most of every start-up
// (pt-render --help: 0.21-0.30 s, 93% of it relocating them) on them, even in runs that never
// read an image. So they live in a module, pt_oiio (image_read_oiio.cpp, image_write_oiio.cpp),
// which the first call of oiioImageIo() opens with dlopen. Built only when PT_OIIO is ON.
#include <cstdint>
#include <string>
#include <vector>

#include "assets/image/exr_layers.h"
#include "assets/image/image_write.h"
#include "render/scene/scene.h"

namespace pt {

// The functions of image_read_oiio.h and image_write_oiio.h, as the module exports them.
struct OiioImageIo {
    Texture (*decodeTexture)(const std::vector<uint8_t>& bytes, const std::string& extension,
                             const std::string& name, const std::string& filePath);
    void (*writeExrChannels)(const std::string& file, const std::string& path, uint32_t width,
                             uint32_t height, const std::vector<ExrChannelSource>& channels,
                             const ImageMetadata& metadata);
    void (*writeDisplayImage)(const std::string& file, const std::string& path, uint32_t width,
                              uint32_t height, const uint8_t* rgb, const ImageMetadata& metadata);
    std::vector<float> (*readImageRgba)(const std::string& path, uint32_t& width, uint32_t& height);
    ExrImage (*readExrChannels)(const std::string& path);
    ImageMetadata (*readImageMetadata)(const std::string& path);
};

// The module's functions; opens it on the first call (thread-safe). Throws InputError naming
// the module when it cannot be opened (a broken install), and retries on the next call.
const OiioImageIo& oiioImageIo();

}  // namespace pt

// The one symbol the module exports: its table of functions.
extern "C" const void* ptOiioImageIo();  // an OiioImageIo, typed as plugin_module.h calls it
