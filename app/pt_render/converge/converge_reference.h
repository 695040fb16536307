#pragma once
// The image `pt-render converge` measures against: a reference EXR (with the noise estimate
// `pt-render reference` stores in it) or, for scenes with an analytic answer such as a white
// furnace, a constant colour.
#include <cstdint>
#include <string>
#include <vector>

namespace pt::cli {

struct ConvergeReference {
    std::vector<float> rgba;
    double noiseRelMse = 0.0;  // the reference's own expected relMSE against the truth (0: exact or unknown)
};

// Throws std::runtime_error naming `path` when it cannot be read or is not width x height.
ConvergeReference readReferenceImage(const std::string& path, uint32_t width, uint32_t height);

// "R,G,B" (or one number for grey), each finite and >= 0; throws UsageError otherwise.
ConvergeReference constantReference(const std::string& rgb, uint32_t width, uint32_t height);

}  // namespace pt::cli
