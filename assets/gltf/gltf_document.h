#pragma once
// Reading a .gltf or .glb into a tinygltf::Model, safely: the GLB container is checked
// here, the JSON by checkGltfJson, and only then does tinygltf parse it. tinygltf's image
// decoding is replaced by a callback that keeps the encoded bytes, so images are decoded
// (or reported as undecodable) by our own reader, once per image that a material uses. A
// .glb's BIN chunk becomes buffer 0 without a copy (gltf_glb_bin.h); a .gltf's external buffer
// files are mapped, not read (gltf_external_buffers.h).
// Internal to pt_assets.
#include <string>

#include "assets/gltf/gltf_context.h"

namespace pt {

// Throws InputError naming the file and the element.
GltfDocument loadGltfDocument(const std::string& path);

}  // namespace pt
