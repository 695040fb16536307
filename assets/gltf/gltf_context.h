#pragma once
// State shared by the stages of one glTF import (document, meshes, materials, textures,
// nodes): the parsed model, the Scene being filled, the caches that make each glTF mesh,
// material and image land in the Scene once, and the helpers every stage uses to name the
// file and the element in its messages. Internal to pt_assets.
#include <tiny_gltf.h>

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "assets/input_error.h"
#include "assets/mapped_file.h"
#include "render/animation/skin_vertex.h"
#include "render/scene/scene.h"

namespace pt {

struct GltfDocument {
    std::string label;    // file name as messages start with it ("Box.gltf")
    std::string path;     // as given
    std::string baseDir;  // folder of the file, for external buffers and images
    tinygltf::Model model;
    // Files mapped for the import (mapped_file.h): a .glb itself, a .gltf's buffer files.
    std::vector<MappedFile> mappedFiles;
    // Buffers whose bytes lie in those files (a .glb's BIN chunk: gltf_glb_bin.h; a buffer
    // file: gltf_external_buffers.h); tinygltf's model holds a stand-in for each.
    std::map<int, Span<const uint8_t>> mappedBuffers;
};

// Buffer `index`'s bytes (an index the caller checked): in a mapped file, else tinygltf's.
inline Span<const uint8_t> gltfBufferBytes(const GltfDocument& doc, int index) {
    if (const auto mapped = doc.mappedBuffers.find(index); mapped != doc.mappedBuffers.end())
        return mapped->second;
    const std::vector<unsigned char>& data = doc.model.buffers[size_t(index)].data;
    return {data.data(), uint32_t(data.size())};
}

// One glTF mesh as it landed in the Scene: the Scene mesh and, per mesh slot, the glTF
// material of the primitive that owns the slot (-1: the glTF default material) and the one
// each material variant gives it (gltf_variants.h; kUnmappedVariant: its default).
struct ImportedMesh {
    uint32_t sceneMesh = 0;
    std::vector<int> slotMaterials;
    std::vector<std::vector<int>> slotVariantMaterials;  // [slot][variant]
    // Parallel to the Scene mesh's positions, or empty: the skin influences the primitives
    // give (zero weights for a primitive that gives none).
    std::vector<JointInfluences> influences;
};

struct GltfContext {
    const GltfDocument& doc;
    Scene& scene;
    int32_t object = -1;
    std::vector<std::string> variants;  // KHR_materials_variants names (gltf_variants.h)

    std::map<int, std::optional<ImportedMesh>> meshes;  // nullopt: no triangles, not placed
    std::map<int, uint32_t> materials;                  // -1 is the default material
    // glTF image -> the Scene texture first made from it (-1: it could not be decoded); a
    // second sampler on the same image copies those texels instead of decoding again.
    std::map<int, int32_t> images;
    std::map<std::tuple<int, WrapMode, WrapMode, bool>, int32_t> textures;
    std::set<int> textureWarnings;  // textures already warned about
    // Attribute values decoded from a compressed primitive (KHR_draco_mesh_compression:
    // gltf_draco.h), returned by the accessor reader in place of the accessor's (absent) buffer
    // data. Filled as the primitive that owns them is read, hence mutable.
    mutable std::map<int, std::vector<float>> decodedFloats;  // the accessor's components each
    // BufferViews decoded from their compressed bytes (EXT_meshopt_compression: gltf_meshopt.h),
    // decoded on first read.
    mutable std::map<int, std::vector<uint8_t>> decodedViews;

    const tinygltf::Model& model() const { return doc.model; }

    [[noreturn]] void fail(const std::string& element, const std::string& what) const {
        throw InputError(doc.label + ": " + element + ": " + what);
    }
    void warn(const std::string& element, const std::string& what) const {
        scene.warnings.push_back(doc.label + ": " + (element.empty() ? "" : element + ": ") + what);
    }
};

// The element `index` of `items`, or an InputError "<file>: <element>: <kind> <index> does
// not exist (<n> in the file)". Every glTF index goes through here before use.
template <class T>
const T& gltfElement(const GltfContext& ctx, const std::vector<T>& items, int index,
                     const std::string& element, const char* kind) {
    if (index < 0 || size_t(index) >= items.size()) {
        ctx.fail(element, std::string(kind) + " " + std::to_string(index) + " does not exist (" +
                              std::to_string(items.size()) + " in the file)");
    }
    return items[size_t(index)];
}

// "meshes[3].primitives[1]" and friends.
inline std::string gltfPath(const char* array, size_t index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

}  // namespace pt
