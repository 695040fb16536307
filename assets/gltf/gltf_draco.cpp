#include "assets/gltf/gltf_draco.h"

#include <algorithm>

#include "assets/gltf/gltf_accessors.h"
#if PT_HAVE_DRACO
#include "assets/gltf/draco_decoder.h"
#include "assets/plugin_module.h"
#endif

namespace pt {

#if PT_HAVE_DRACO

const DracoDecoder& dracoDecoder() {
    static const DracoDecoder* const table = static_cast<const DracoDecoder*>(
        openModuleTable(PT_DRACO_MODULE, "ptDracoDecoder", "the Draco decoder"));
    return *table;
}

namespace {

// The attribute `name` (Draco attribute id `id`) as the floats of its accessor.
void takeAttribute(const GltfContext& ctx, const tinygltf::Primitive& primitive, DracoMesh& mesh,
                   const std::string& name, int id, const std::string& element) {
    const auto it = primitive.attributes.find(name);
    if (it == primitive.attributes.end())
        ctx.fail(element, "attribute " + name + " is not one of the primitive's");
    const int accessor = it->second;
    const auto& acc =
        gltfElement(ctx, ctx.model().accessors, accessor, element, (name + " accessor").c_str());
    const auto attribute = std::find_if(mesh.attributes.begin(), mesh.attributes.end(),
                                        [id](const DracoMesh::Attribute& a) { return int64_t(a.id) == id; });
    if (attribute == mesh.attributes.end())
        ctx.fail(element, "attribute " + name + ": the Draco data has no attribute " + std::to_string(id));
    const int components = gltfTypeComponents(acc.type);
    if (components == 0 || attribute->components != components) {
        ctx.fail(element, "attribute " + name + " has " + std::to_string(attribute->components) +
                              " components in the Draco data, " + std::to_string(components) +
                              " in its accessor");
    }
    if (acc.count != mesh.points) {
        ctx.fail(element, "attribute " + name + ": its accessor counts " + std::to_string(acc.count) +
                              " elements, the Draco data " + std::to_string(mesh.points) + " points");
    }
    ctx.decodedFloats[accessor] = std::move(attribute->values);
}

}  // namespace

bool gltfDracoAvailable() { return true; }

std::optional<std::vector<uint32_t>> decodeGltfDraco(const GltfContext& ctx,
                                                     const tinygltf::Primitive& primitive,
                                                     const std::string& element) {
    const auto found = primitive.extensions.find(kDracoExtension);
    if (found == primitive.extensions.end()) return std::nullopt;
    const std::string where = element + ".extensions." + kDracoExtension;
    const tinygltf::Value& extension = found->second;
    const tinygltf::Value& view = extension.Get("bufferView");
    const tinygltf::Value& attributes = extension.Get("attributes");
    if (!view.IsInt() || !attributes.IsObject()) ctx.fail(where, "needs a bufferView and attributes");
    const std::vector<uint8_t> bytes = readGltfBufferView(ctx, view.GetNumberAsInt(), where);
    DracoMesh mesh = dracoDecoder().decode(bytes.data(), bytes.size());
    if (!mesh.error.empty()) ctx.fail(where, "Draco data cannot be decoded: " + mesh.error);
    for (const std::string& name : attributes.Keys()) {
        const tinygltf::Value& id = attributes.Get(name);
        takeAttribute(ctx, primitive, mesh, name, id.IsInt() ? id.GetNumberAsInt() : -1, where);
    }
    // The indices accessor only counts the corners (gltf_tinygltf_compat.h may have moved it
    // into the extension).
    const tinygltf::Value& moved = extension.Get("indices");
    const int indices = primitive.indices >= 0 ? primitive.indices
                        : moved.IsInt()        ? moved.GetNumberAsInt()
                                               : -1;
    if (indices < 0) ctx.fail(where, "the primitive has no indices accessor for the Draco faces");
    const size_t expected = gltfAccessorCount(ctx, indices, {where, std::string("indices")});
    if (mesh.corners.size() != expected) {
        ctx.fail(where, "indices: its accessor counts " + std::to_string(expected) + ", the Draco data " +
                            std::to_string(mesh.corners.size()) + " corners");
    }
    return std::move(mesh.corners);
}

#else

bool gltfDracoAvailable() { return false; }

std::optional<std::vector<uint32_t>> decodeGltfDraco(const GltfContext&, const tinygltf::Primitive&,
                                                     const std::string&) {
    return std::nullopt;
}

#endif

}  // namespace pt
