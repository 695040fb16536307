#include "assets/gltf_mesh.h"

#include <limits>

#include "assets/gltf_primitive.h"

namespace pt {
namespace {

// Appends one primitive's geometry; its triangles take slot `slot`.
void appendPrimitive(const GltfContext& ctx, PrimitiveGeometry& g, uint32_t slot, Mesh& mesh,
                     std::vector<uint32_t>& slots, const std::string& element) {
    const size_t base = mesh.positions.size();
    if (g.positions.size() > std::numeric_limits<uint32_t>::max() - base) {
        ctx.fail(element, "more than 2^32 vertices");
    }
    mesh.positions.insert(mesh.positions.end(), g.positions.begin(), g.positions.end());
    mesh.normals.insert(mesh.normals.end(), g.normals.begin(), g.normals.end());
    if (!g.uvs.empty()) {
        mesh.uvs.resize(base);  // earlier primitives without TEXCOORD_0 get (0, 0)
        mesh.uvs.insert(mesh.uvs.end(), g.uvs.begin(), g.uvs.end());
    }
    if (!g.tangents.empty()) {
        mesh.tangents.resize(base);  // zero: "derive from the UVs" for primitives without TANGENT
        mesh.tangents.insert(mesh.tangents.end(), g.tangents.begin(), g.tangents.end());
    }
    for (uint32_t index : g.indices) mesh.indices.push_back(uint32_t(base) + index);
    slots.insert(slots.end(), g.indices.size() / 3, slot);
}

}  // namespace

const std::optional<ImportedMesh>& importGltfMesh(GltfContext& ctx, int meshIndex,
                                                  const std::string& element) {
    if (auto it = ctx.meshes.find(meshIndex); it != ctx.meshes.end()) return it->second;
    const auto& source = gltfElement(ctx, ctx.model().meshes, meshIndex, element, "mesh");
    const std::string meshElement = gltfPath("meshes", size_t(meshIndex));
    Mesh mesh;
    mesh.name = source.name.empty() ? meshElement : source.name;
    ImportedMesh imported;
    std::vector<uint32_t> slots;
    for (size_t p = 0; p < source.primitives.size(); ++p) {
        std::optional<PrimitiveGeometry> g = readGltfPrimitive(ctx, size_t(meshIndex), p);
        if (!g) continue;
        const int material = source.primitives[p].material;
        if (material >= 0) {
            gltfElement(ctx, ctx.model().materials, material,
                        meshElement + ".primitives[" + std::to_string(p) + "]", "material");
        }
        appendPrimitive(ctx, *g, uint32_t(imported.slotMaterials.size()), mesh, slots, meshElement);
        imported.slotMaterials.push_back(material);
    }
    if (imported.slotMaterials.empty()) {
        ctx.warn(meshElement, "has no triangles to render; nodes using it are not placed");
        return ctx.meshes[meshIndex] = std::nullopt;
    }
    if (!mesh.uvs.empty()) mesh.uvs.resize(mesh.positions.size());
    if (!mesh.tangents.empty()) mesh.tangents.resize(mesh.positions.size());
    mesh.slotCount = uint32_t(imported.slotMaterials.size());
    if (mesh.slotCount > 1) mesh.primitiveSlots = std::move(slots);
    imported.sceneMesh = uint32_t(ctx.scene.meshes.size());
    ctx.scene.meshes.push_back(std::move(mesh));
    return ctx.meshes[meshIndex] = std::move(imported);
}

}  // namespace pt
