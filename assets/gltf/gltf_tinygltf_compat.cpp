#include "assets/gltf/gltf_tinygltf_compat.h"

namespace pt {
namespace {

bool hasBufferView(const nlohmann::json& root, const nlohmann::json& index) {
    if (!index.is_number_unsigned() || !root.contains("accessors") || !root["accessors"].is_array())
        return true;
    const nlohmann::json& accessors = root["accessors"];
    const size_t i = index.get<size_t>();
    return i >= accessors.size() || !accessors[i].is_object() || accessors[i].contains("bufferView");
}

}  // namespace

void standInForTinygltf(nlohmann::json& buffer) {
    buffer["uri"] = kTinygltfStandInUri;
    buffer["byteLength"] = 4;
}

bool isMeshoptFallbackBuffer(const nlohmann::json& buffer) {
    if (!buffer.is_object() || !buffer.contains("extensions")) return false;
    const nlohmann::json& extensions = buffer["extensions"];
    if (!extensions.is_object() || !extensions.contains("EXT_meshopt_compression")) return false;
    const nlohmann::json& meshopt = extensions["EXT_meshopt_compression"];
    if (!meshopt.is_object() || !meshopt.contains("fallback")) return false;
    const nlohmann::json& fallback = meshopt["fallback"];
    return fallback.is_boolean() && fallback.get<bool>();
}

namespace {

bool emptyFallbackBuffers(nlohmann::json& root) {
    bool changed = false;
    if (!root.contains("buffers") || !root["buffers"].is_array()) return false;
    for (nlohmann::json& buffer : root["buffers"]) {
        if (!isMeshoptFallbackBuffer(buffer) || buffer.contains("uri")) continue;
        standInForTinygltf(buffer);
        changed = true;
    }
    return changed;
}

}  // namespace

bool adaptGltfForTinygltf(nlohmann::json& root) {
    if (!root.is_object()) return false;
    bool changed = emptyFallbackBuffers(root);
    if (!root.contains("meshes") || !root["meshes"].is_array()) return changed;
    for (nlohmann::json& mesh : root["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
        for (nlohmann::json& primitive : mesh["primitives"]) {
            if (!primitive.is_object() || !primitive.contains("indices") || !primitive.contains("extensions"))
                continue;
            nlohmann::json& extensions = primitive["extensions"];
            if (!extensions.is_object() || !extensions.contains("KHR_draco_mesh_compression")) continue;
            nlohmann::json& draco = extensions["KHR_draco_mesh_compression"];
            if (!draco.is_object() || hasBufferView(root, primitive["indices"])) continue;
            draco["indices"] = primitive["indices"];
            primitive.erase("indices");
            changed = true;
        }
    }
    return changed;
}

}  // namespace pt
