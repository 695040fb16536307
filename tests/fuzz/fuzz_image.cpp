// Fuzz target: image reading as textures are read from files (readTextureFile): the format is
// sniffed from the bytes (PNG, JPEG, HDR, EXR, TIFF, WebP, GIF, BMP; KTX2 refused), else taken
// from the file's extension, .tga here; PNG chunks are checked; then the build's decoder and
// the expansion to RGBA. run_fuzz.sh builds without OpenImageIO, so the decoder is stb_image
// (Debian's shared libstb, not instrumented: ASan sees its faults, not its silent
// out-of-bounds reads); PT_FUZZ_OIIO=ON fuzzes OpenImageIO's readers instead. glTF's embedded
// images (decodeTextureFromMemory) take the same path without a file.
#include "assets/image/image_read.h"
#include "fuzz_load.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    pt::fuzz::readWrittenInput("image.tga", data, size,
                               [](const std::string& path) { pt::readTextureFile(path); });
    return 0;
}
