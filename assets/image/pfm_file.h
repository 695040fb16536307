#pragma once
// Portable float maps (.pfm): uncompressed 32-bit float RGB, the one lossless HDR format that
// needs no library. The GPU machine's build has no OpenImageIO (so no EXR), yet its references
// for `pt-render converge` must keep full float precision: they are written and read as PFM
// there, and any build reads them. No metadata: the format has none.
#include <cstdint>
#include <string>
#include <vector>

namespace pt {

bool isPfmPath(const std::string& path);  // the extension is .pfm (any case)

// RGBA float (row-major from the top; A is dropped) -> little-endian RGB PFM, atomically.
// Throws InputError naming `path` on failure.
void writePfm(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgba);

// "PF" (RGB) or "Pf" (grey) of either byte order -> RGBA float (A = 1), rows from the top.
// Throws InputError naming `path` and what is wrong with it.
std::vector<float> readPfm(const std::string& path, uint32_t& width, uint32_t& height);

}  // namespace pt
