// Fuzz target: the portable float map reader (readPfm) that reads `pt-render converge`
// references: the "PF"/"Pf" header, its width, height and scale (byte order), and the rows.
#include "assets/image/pfm_file.h"
#include "fuzz_load.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    pt::fuzz::readWrittenInput("image.pfm", data, size, [](const std::string& path) {
        uint32_t width = 0, height = 0;
        pt::readPfm(path, width, height);
    });
    return 0;
}
