#pragma once
// KHR_draco_mesh_compression: a primitive's attributes and indices decoded from its Draco
// bitstream (Google's Draco, Debian's libdraco-dev; draco_decoder.h) into the values its
// accessors stand for, kept in GltfContext::decodedFloats where the accessor readers find them,
// so the rest of the primitive's import (checks, normals, tangents) runs unchanged. Every id and
// count is checked: an attribute the bitstream lacks, a count that differs from its accessor's,
// an index past the points decoded are errors naming the primitive. Internal to pt_assets.
#include <optional>
#include <string>
#include <vector>

#include "assets/gltf/gltf_context.h"

namespace pt {

constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

// Whether this build decodes Draco (libdraco was found).
bool gltfDracoAvailable();

// Decodes `primitive`'s Draco data when it has any: its attributes go to
// GltfContext::decodedFloats, its triangles' corners are returned (point indices, three a
// triangle, not yet checked against the points). nullopt where it has none (or the build
// cannot decode it). Throws InputError where the data is malformed.
std::optional<std::vector<uint32_t>> decodeGltfDraco(const GltfContext& ctx,
                                                     const tinygltf::Primitive& primitive,
                                                     const std::string& element);

}  // namespace pt
