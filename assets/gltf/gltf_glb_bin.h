#pragma once
// The BIN chunk of a .glb read where it lies in the mapped file, without a copy. tinygltf 2.7
// copies the chunk into buffer 0 (a fresh array as large as the file, zeroed, then filled): the
// 10M-triangle sphere as a .glb loaded in 0.36-0.41 s on a 2-core machine, against 0.28-0.34 s
// as .gltf and .bin. So tinygltf parses the JSON with buffer 0, and every image in a bufferView
// (whose bytes tinygltf would read at load), standing in as 4-byte data URIs; then buffer 0's
// bytes are the chunk's in the mapped file (GltfDocument::mappedBuffers) and the images get their
// bufferViews back.
// Internal to pt_assets.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "assets/gltf/gltf_context.h"

namespace pt {

// What detachGlbBin took out of the JSON, for attachGlbBin to put back.
struct DetachedGlbBin {
    // An image in a bufferView as tinygltf would have parsed it (a data URI overwrites the
    // image's mimeType with its own).
    struct ImageView {
        size_t image = 0;
        int bufferView = -1, width = 0, height = 0;
        std::string mimeType;
    };
    size_t byteLength = 0;  // buffer 0's
    std::vector<ImageView> imageViews;
};

// Rewrites `root` (checked by checkGltfJson, adapted by adaptGltfForTinygltf) as above, where
// buffer 0 is the only buffer without a uri; otherwise nullopt and `root` as it was.
std::optional<DetachedGlbBin> detachGlbBin(nlohmann::json& root);

// Buffer 0 without the stand-in's bytes (the caller points GltfDocument::mappedBuffers at the
// chunk), and the images as tinygltf leaves images in bufferViews.
void attachGlbBin(tinygltf::Model& model, const DetachedGlbBin& detached);

}  // namespace pt
