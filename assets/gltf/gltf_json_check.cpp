#include "assets/gltf/gltf_json_check.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "assets/gltf/gltf_tinygltf_compat.h"
#include "assets/gltf/gltf_uri.h"
#include "assets/input_error.h"
#include "assets/message_text.h"

// Sections: the document's shape; index references; byte counts; bufferView extents;
// buffer sources.

namespace pt {
namespace {

using nlohmann::json;

// JSON numbers above 2^53 are not exact; no real buffer comes near.
constexpr uint64_t kMaxByteCount = uint64_t(1) << 53;

[[noreturn]] void fail(const GltfJsonSource& source, const std::string& path, const std::string& what) {
    throw InputError(source.label + ": " + (path.empty() ? "" : path + ": ") + what);
}

size_t sectionSize(const json& root, const char* key) {
    auto it = root.find(key);
    return it != root.end() && it->is_array() ? it->size() : 0;
}

// --- The document's shape ------------------------------------------------------------

void checkShape(const json& root, const GltfJsonSource& source) {
    if (!root.is_object()) fail(source, "", "the document is not a JSON object");
    auto asset = root.find("asset");
    if (asset == root.end() || !asset->is_object()) fail(source, "asset", "missing");
    auto version = asset->find("version");
    if (version == asset->end() || !version->is_string()) {
        fail(source, "asset.version", "missing");
    }
    if (version->get<std::string>().rfind("2.", 0) != 0) {
        fail(source, "asset.version",
             "glTF " + version->get<std::string>() + " is not supported (expected 2.x)");
    }
    for (const char* key : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images",
                            "materials", "meshes", "nodes", "samplers", "scenes", "skins", "textures"}) {
        auto it = root.find(key);
        if (it == root.end()) continue;
        if (!it->is_array()) fail(source, key, "expected an array");
        for (size_t i = 0; i < it->size(); ++i) {
            if (!(*it)[i].is_object()) {
                fail(source, std::string(key) + "[" + std::to_string(i) + "]", "expected a JSON object");
            }
        }
    }
}

// --- Index references ----------------------------------------------------------------

// A reference's location as a path pattern: "name" steps into an object member, "[]" visits
// every element of an array, "{}" every value of an object. Ordered from the meshes down to
// the buffers, so the first error reported is the one nearest to what the file draws.
struct Reference {
    const char* pattern;
    const char* target;  // top-level array the index points into
    const char* kind;    // singular, for messages
};

constexpr Reference kReferences[] = {
    {"scene", "scenes", "scene"},
    {"scenes[].nodes[]", "nodes", "node"},
    {"nodes[].children[]", "nodes", "node"},
    {"nodes[].mesh", "meshes", "mesh"},
    {"nodes[].camera", "cameras", "camera"},
    {"nodes[].skin", "skins", "skin"},
    {"meshes[].primitives[].indices", "accessors", "accessor"},
    {"meshes[].primitives[].attributes{}", "accessors", "accessor"},
    {"meshes[].primitives[].targets[]{}", "accessors", "accessor"},
    {"meshes[].primitives[].material", "materials", "material"},
    {"materials[].pbrMetallicRoughness.baseColorTexture.index", "textures", "texture"},
    {"materials[].pbrMetallicRoughness.metallicRoughnessTexture.index", "textures", "texture"},
    {"materials[].normalTexture.index", "textures", "texture"},
    {"materials[].occlusionTexture.index", "textures", "texture"},
    {"materials[].emissiveTexture.index", "textures", "texture"},
    {"materials[].extensions{}{}.index", "textures", "texture"},
    {"textures[].source", "images", "image"},
    {"textures[].sampler", "samplers", "sampler"},
    {"images[].bufferView", "bufferViews", "bufferView"},
    {"skins[].joints[]", "nodes", "node"},
    {"skins[].skeleton", "nodes", "node"},
    {"skins[].inverseBindMatrices", "accessors", "accessor"},
    {"animations[].samplers[].input", "accessors", "accessor"},
    {"animations[].samplers[].output", "accessors", "accessor"},
    {"animations[].channels[].target.node", "nodes", "node"},
    {"accessors[].bufferView", "bufferViews", "bufferView"},
    {"accessors[].sparse.indices.bufferView", "bufferViews", "bufferView"},
    {"accessors[].sparse.values.bufferView", "bufferViews", "bufferView"},
    {"bufferViews[].buffer", "buffers", "buffer"},
};

struct Step {
    enum Kind { Member, EachElement, EachValue } kind;
    std::string name;
};

std::vector<Step> parsePattern(const std::string& pattern) {
    std::vector<Step> steps;
    size_t i = 0;
    while (i < pattern.size()) {
        if (pattern[i] == '.') {
            ++i;
        } else if (pattern.compare(i, 2, "[]") == 0) {
            steps.push_back({Step::EachElement, ""});
            i += 2;
        } else if (pattern.compare(i, 2, "{}") == 0) {
            steps.push_back({Step::EachValue, ""});
            i += 2;
        } else {
            const size_t end = pattern.find_first_of(".[{", i);
            steps.push_back({Step::Member, pattern.substr(i, end - i)});
            i = end == std::string::npos ? pattern.size() : end;
        }
    }
    return steps;
}

using Visit = std::function<void(const json&, const std::string&)>;

// Visits every value the steps reach; values of the wrong JSON type along the way are not
// references (tinygltf reports those shapes itself).
void walk(const json& value, const std::vector<Step>& steps, size_t i, const std::string& path,
          const Visit& visit) {
    if (i == steps.size()) return visit(value, path);
    const Step& step = steps[i];
    if (step.kind == Step::Member) {
        if (!value.is_object()) return;
        auto it = value.find(step.name);
        if (it == value.end()) return;
        walk(*it, steps, i + 1, path.empty() ? step.name : path + "." + step.name, visit);
    } else if (step.kind == Step::EachElement) {
        if (!value.is_array()) return;
        for (size_t k = 0; k < value.size(); ++k) {
            walk(value[k], steps, i + 1, path + "[" + std::to_string(k) + "]", visit);
        }
    } else {
        if (!value.is_object()) return;
        for (auto it = value.begin(); it != value.end(); ++it) {
            walk(it.value(), steps, i + 1, path + "." + it.key(), visit);
        }
    }
}

void checkReferences(const json& root, const GltfJsonSource& source) {
    for (const Reference& ref : kReferences) {
        const size_t count = sectionSize(root, ref.target);
        walk(root, parsePattern(ref.pattern), 0, "", [&](const json& v, const std::string& path) {
            if (!v.is_number_integer() || v.get<int64_t>() < 0) {
                fail(source, path,
                     std::string("expected the index of a ") + ref.kind + ", got " + shortened(v.dump()));
            }
            if (v.get<uint64_t>() >= count) {
                fail(source, path,
                     std::string(ref.kind) + " " + shortened(v.dump()) + " does not exist (" +
                         std::to_string(count) + " in the file)");
            }
        });
    }
}

// --- Byte counts and enumerations -----------------------------------------------------

// A member that must be a whole number >= `min` (absent: `fallback`, or an error when
// `fallback` is empty).
uint64_t wholeNumber(const json& object, const char* key, const std::string& path, uint64_t min,
                     std::optional<uint64_t> fallback, const GltfJsonSource& source) {
    auto it = object.find(key);
    const std::string where = path + "." + key;
    if (it == object.end()) {
        if (!fallback) fail(source, where, "missing");
        return *fallback;
    }
    if (!it->is_number_integer() || it->get<int64_t>() < 0 || it->get<uint64_t>() > kMaxByteCount) {
        fail(source, where, "expected a whole number, got " + shortened(it->dump()));
    }
    const uint64_t value = it->get<uint64_t>();
    if (value < min) {
        fail(source, where, "must be at least " + std::to_string(min) + ", got " + shortened(it->dump()));
    }
    return value;
}

bool isComponentType(uint64_t type) {
    return type == 5120 || type == 5121 || type == 5122 || type == 5123 || type == 5125 || type == 5126;
}

void checkAccessorFields(const json& accessor, const std::string& path, const GltfJsonSource& source) {
    wholeNumber(accessor, "byteOffset", path, 0, 0, source);
    wholeNumber(accessor, "count", path, 1, std::nullopt, source);
    const uint64_t componentType = wholeNumber(accessor, "componentType", path, 0, std::nullopt, source);
    if (!isComponentType(componentType)) {
        fail(source, path + ".componentType",
             std::to_string(componentType) + " is not a glTF component type");
    }
    auto type = accessor.find("type");
    static const char* kTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
    bool known = false;
    for (const char* t : kTypes) known = known || (type != accessor.end() && *type == t);
    if (!known) {
        fail(source, path + ".type",
             type == accessor.end() ? std::string("missing")
                                    : shortened(type->dump()) + " is not a glTF accessor type");
    }
    auto sparse = accessor.find("sparse");
    if (sparse == accessor.end()) return;
    if (!sparse->is_object()) fail(source, path + ".sparse", "expected a JSON object");
    // tinygltf keeps these as int; larger values would wrap there.
    auto intSized = [&](const json& object, const char* key, const std::string& where, uint64_t min,
                        std::optional<uint64_t> fallback) {
        if (wholeNumber(object, key, where, min, fallback, source) > uint64_t(INT32_MAX)) {
            fail(source, where + "." + key, "too large");
        }
    };
    intSized(*sparse, "count", path + ".sparse", 1, std::nullopt);
    for (const char* part : {"indices", "values"}) {
        auto it = sparse->find(part);
        const std::string where = path + ".sparse." + part;
        if (it == sparse->end() || !it->is_object()) fail(source, where, "missing");
        wholeNumber(*it, "bufferView", where, 0, std::nullopt, source);
        intSized(*it, "byteOffset", where, 0, 0);
    }
    const uint64_t indexType = wholeNumber(sparse->at("indices"), "componentType", path + ".sparse.indices",
                                           0, std::nullopt, source);
    if (indexType != 5121 && indexType != 5123 && indexType != 5125) {
        fail(source, path + ".sparse.indices.componentType",
             std::to_string(indexType) + " is not an unsigned integer type");
    }
}

void checkBufferViewFields(const json& view, const std::string& path, const GltfJsonSource& source) {
    wholeNumber(view, "buffer", path, 0, std::nullopt, source);
    wholeNumber(view, "byteOffset", path, 0, 0, source);
    wholeNumber(view, "byteLength", path, 1, std::nullopt, source);
    const uint64_t stride = wholeNumber(view, "byteStride", path, 0, 0, source);
    if (stride != 0 && (stride < 4 || stride > 252 || stride % 4 != 0)) {
        fail(source, path + ".byteStride", std::to_string(stride) + " is not a multiple of 4 in [4, 252]");
    }
}

void checkByteFields(const json& root, const GltfJsonSource& source) {
    for (size_t i = 0; i < sectionSize(root, "accessors"); ++i) {
        checkAccessorFields(root.at("accessors").at(i), "accessors[" + std::to_string(i) + "]", source);
    }
    for (size_t i = 0; i < sectionSize(root, "bufferViews"); ++i) {
        checkBufferViewFields(root.at("bufferViews").at(i), "bufferViews[" + std::to_string(i) + "]", source);
    }
    for (size_t i = 0; i < sectionSize(root, "buffers"); ++i) {
        wholeNumber(root.at("buffers").at(i), "byteLength", "buffers[" + std::to_string(i) + "]", 1,
                    std::nullopt, source);
    }
}

// --- bufferView extents ----------------------------------------------------------------

void checkBufferViewExtents(const json& root, const GltfJsonSource& source) {
    for (size_t i = 0; i < sectionSize(root, "bufferViews"); ++i) {
        const json& view = root.at("bufferViews").at(i);
        const uint64_t buffer = view.at("buffer").get<uint64_t>();
        const uint64_t offset = view.value("byteOffset", uint64_t(0));
        const uint64_t length = view.at("byteLength").get<uint64_t>();
        const uint64_t bufferLength = root.at("buffers").at(buffer).at("byteLength").get<uint64_t>();
        if (offset > bufferLength || length > bufferLength - offset) {
            fail(source, "bufferViews[" + std::to_string(i) + "]",
                 "bytes [" + std::to_string(offset) + ", " + std::to_string(offset + length) +
                     ") run past the end of buffer " + std::to_string(buffer) + " (" +
                     std::to_string(bufferLength) + " bytes)");
        }
    }
}

// --- Buffer sources --------------------------------------------------------------------

// Bytes a base64 payload decodes to, or nullopt when it is not base64.
std::optional<uint64_t> base64DecodedSize(const std::string& payload) {
    if (payload.size() % 4 != 0) return std::nullopt;
    size_t padding = 0;
    while (padding < 2 && padding < payload.size() && payload[payload.size() - 1 - padding] == '=') {
        ++padding;
    }
    return payload.size() / 4 * 3 - padding;
}

void checkDataUri(const std::string& uri, uint64_t byteLength, const std::string& path,
                  const GltfJsonSource& source) {
    // The two buffer media types tinygltf decodes; any other fails inside tinygltf.
    for (const char* prefix :
         {"data:application/octet-stream;base64,", "data:application/gltf-buffer;base64,"}) {
        if (uri.rfind(prefix, 0) != 0) continue;
        const auto bytes = base64DecodedSize(uri.substr(std::string(prefix).size()));
        if (!bytes) fail(source, path + ".uri", "the data URI is not valid base64");
        if (*bytes != byteLength) {
            fail(source, path,
                 "the data URI holds " + std::to_string(*bytes) + " bytes but byteLength is " +
                     std::to_string(byteLength));
        }
        return;
    }
    fail(source, path + ".uri",
         "unsupported data URI type '" + uri.substr(0, std::min<size_t>(uri.find(','), 60)) + "'");
}

void checkExternalFile(const std::string& uri, uint64_t byteLength, const std::string& path,
                       const GltfJsonSource& source) {
    namespace fs = std::filesystem;
    const std::string name = decodeGltfUri(uri);
    const fs::path file = fs::path(source.baseDir) / name;
    std::error_code error;
    if (!fs::is_regular_file(file, error)) {
        fail(source, path + ".uri", "buffer file '" + name + "' not found");
    }
    const uint64_t size = fs::file_size(file, error);
    // tinygltf 2.7 insists on an exact match; say so here, with the names.
    if (error || size != byteLength) {
        fail(source, path,
             "'" + name + "' holds " + std::to_string(size) + " bytes but byteLength is " +
                 std::to_string(byteLength));
    }
}

void checkBufferSources(const json& root, const GltfJsonSource& source) {
    for (size_t i = 0; i < sectionSize(root, "buffers"); ++i) {
        const json& buffer = root.at("buffers").at(i);
        const std::string path = "buffers[" + std::to_string(i) + "]";
        const uint64_t byteLength = buffer.at("byteLength").get<uint64_t>();
        auto uri = buffer.find("uri");
        if (uri == buffer.end() && isMeshoptFallbackBuffer(buffer)) {
            continue;  // no bytes: the views on it are decoded from another (gltf_meshopt.h)
        } else if (uri == buffer.end()) {
            if (!source.glbBinBytes || i != 0) {
                fail(source, path, "has no uri (only the first buffer of a .glb may omit it)");
            }
            if (byteLength > *source.glbBinBytes) {
                fail(source, path,
                     "byteLength " + std::to_string(byteLength) + " is larger than the GLB BIN chunk (" +
                         std::to_string(*source.glbBinBytes) + " bytes)");
            }
        } else if (!uri->is_string()) {
            fail(source, path + ".uri", "expected a string");
        } else if (uri->get<std::string>().rfind("data:", 0) == 0) {
            checkDataUri(uri->get<std::string>(), byteLength, path, source);
        } else {
            checkExternalFile(uri->get<std::string>(), byteLength, path, source);
        }
    }
}

}  // namespace

void checkGltfJson(const nlohmann::json& root, const GltfJsonSource& source) {
    try {
        checkShape(root, source);
        checkReferences(root, source);
        checkByteFields(root, source);
        checkBufferViewExtents(root, source);
        checkBufferSources(root, source);
    } catch (const nlohmann::json::exception& e) {
        // Only reachable if a check above missed a shape it relies on; still bad input.
        throw InputError(source.label + ": malformed glTF JSON: " + e.what());
    }
}

}  // namespace pt
