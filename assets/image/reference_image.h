#pragma once
// A reference image to measure renders against (`pt-render converge`, the editor's live error
// plot): its pixels and the noise estimate `pt-render reference` stores in its metadata.
#include <cstdint>
#include <string>
#include <vector>

namespace pt {

struct ReferenceImage {
    std::string path;
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;   // linear RGBA float, row-major from the top
    double noiseRelMse = 0.0;  // its own expected relMSE against the truth ("pt:noise_relmse"), 0: unknown
};

// Reads any image readImageRgba reads (EXR, PFM, HDR, PNG...). Where the file or the build
// carries no metadata (PFM; no OpenImageIO), the noise stays 0. Throws InputError naming `path`.
ReferenceImage loadReferenceImage(const std::string& path);

}  // namespace pt
