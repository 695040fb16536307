#include "assets/gltf/gltf_external_buffers.h"

#include <filesystem>
#include <set>

#include "assets/gltf/gltf_tinygltf_compat.h"
#include "assets/gltf/gltf_uri.h"

namespace pt {
namespace {

// The buffers that hold a bufferView some image reads.
std::set<size_t> buffersWithImages(const nlohmann::json& root) {
    std::set<size_t> out;
    if (!root.contains("images") || !root.contains("bufferViews")) return out;
    const nlohmann::json& views = root["bufferViews"];
    for (const nlohmann::json& image : root["images"]) {
        if (!image.contains("bufferView")) continue;
        const size_t view = image["bufferView"].get<size_t>();
        out.insert(views.at(view).at("buffer").get<size_t>());
    }
    return out;
}

}  // namespace

std::vector<ExternalBufferFile> detachExternalBuffers(nlohmann::json& root, const std::string& baseDir) {
    std::vector<ExternalBufferFile> files;
    if (!root.contains("buffers")) return files;
    const std::set<size_t> withImages = buffersWithImages(root);
    nlohmann::json& buffers = root["buffers"];
    for (size_t i = 0; i < buffers.size(); ++i) {
        nlohmann::json& buffer = buffers[i];
        if (!buffer.contains("uri") || withImages.count(i)) continue;
        const std::string uri = buffer["uri"].get<std::string>();
        if (uri.rfind("data:", 0) == 0) continue;
        files.push_back({int(i), (std::filesystem::path(baseDir) / decodeGltfUri(uri)).string()});
        standInForTinygltf(buffer);
    }
    return files;
}

}  // namespace pt
