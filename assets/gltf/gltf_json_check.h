#pragma once
// Checks a glTF document's JSON before tinygltf loads it. tinygltf 2.7 dereferences some
// indices and byte ranges while loading (image bufferViews, the GLB BIN chunk), truncates
// 64-bit indices to int, and reports malformed sizes without naming the element; so every
// index reference in the document, every byte count and offset, every bufferView's extent
// inside its buffer, and every buffer's source (GLB chunk, data URI, external file and its
// size) is checked here first, and an InputError names the file and the JSON path of the bad
// element, e.g. "Box.gltf: bufferViews[0].byteLength: expected a whole number of bytes, got
// 1e+300". Accessor ranges are checked where the accessor is read (gltf_accessors.h), where
// the message can also name the mesh and primitive. Internal to pt_assets.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace pt {

struct GltfJsonSource {
    std::string label;                  // file name for messages
    std::string baseDir;                // where external buffers are looked up
    std::optional<size_t> glbBinBytes;  // .glb: size of the BIN chunk (0 when absent)
};

void checkGltfJson(const nlohmann::json& root, const GltfJsonSource& source);

}  // namespace pt
