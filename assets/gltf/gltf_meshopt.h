#pragma once
// EXT_meshopt_compression: a bufferView whose bytes are stored compressed (meshoptimizer's
// vertex and index codecs and its octahedral, quaternion and exponential filters; Debian's
// libmeshoptimizer-dev), decoded on first use into the bytes the view stands for, which the
// accessor reader then reads as any view's. The compressed range is checked against its
// buffer, the mode, stride, count and filter against the extension's rules, and the decoded
// size is bounded before anything is allocated. Internal to pt_assets.
#include <cstdint>
#include <string>
#include <vector>

#include "assets/gltf/gltf_context.h"

namespace pt {

constexpr const char* kMeshoptExtension = "EXT_meshopt_compression";

// Whether this build decodes it (libmeshoptimizer was found).
bool gltfMeshoptAvailable();

// The decoded bytes of bufferView `view`, or nullptr where it is not compressed (or the build
// cannot decode it). Throws InputError naming the view where the data is malformed.
const std::vector<uint8_t>* meshoptView(const GltfContext& ctx, int view);

}  // namespace pt
