#pragma once
// Reading a .gltf or .glb into a tinygltf::Model, safely: the GLB container is checked
// here, the JSON by checkGltfJson, and only then does tinygltf parse it. tinygltf's image
// decoding is replaced by a callback that keeps the encoded bytes, so images are decoded
// (or reported as undecodable) by our own reader, once per image that a material uses. The
// file is mapped, not read (mapped_file.h): a .glb's BIN chunk is buffer 0 where it lies in the
// mapping (gltf_glb_bin.h), and a .gltf's buffer files are mapped too (gltf_external_buffers.h).
// Internal to pt_assets.
#include <string>

#include "assets/gltf/gltf_context.h"

namespace pt {

// Throws InputError naming the file and the element.
GltfDocument loadGltfDocument(const std::string& path);

}  // namespace pt
