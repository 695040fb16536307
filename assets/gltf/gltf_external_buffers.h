#pragma once
// A .gltf's external buffer files mapped, not read (mapped_file.h). tinygltf 2.7 reads each
// into a fresh array: zeroed, then filled by a copy out of the page cache, which on a 2-core
// machine was most of the 10M-triangle sphere's load. So tinygltf parses the JSON with each such
// buffer standing in as a 4-byte data URI, and the import reads the mapped file instead
// (gltfBufferBytes). A buffer holding an image's bufferView stays tinygltf's: it reads those
// images' bytes as it parses.
// Internal to pt_assets.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pt {

struct ExternalBufferFile {
    int buffer = -1;
    std::string path;  // the uri decoded, under the glTF's folder
};

// Rewrites `root` (checked by checkGltfJson, so each file exists and holds byteLength bytes)
// as above and returns the files to map, in buffer order.
std::vector<ExternalBufferFile> detachExternalBuffers(nlohmann::json& root, const std::string& baseDir);

}  // namespace pt
