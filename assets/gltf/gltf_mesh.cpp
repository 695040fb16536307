#include "assets/gltf/gltf_mesh.h"

#include <limits>

#include "assets/gltf/gltf_primitive.h"
#include "assets/gltf/gltf_values.h"
#include "assets/gltf/gltf_variants.h"
#include "render/scene/morph.h"

namespace pt {
namespace {

// Appends the primitive's morph deltas. A primitive without targets in a mesh whose others
// have them is not deformed: zero deltas. Normal deltas are kept only once some primitive
// has them; earlier vertices then get zero.
void appendMorphDeltas(const PrimitiveGeometry& g, size_t base, Mesh& mesh) {
    for (size_t t = 0; t < mesh.morphTargets.size(); ++t) {
        MorphTarget& target = mesh.morphTargets[t];
        if (g.targets.empty()) {
            target.positionDeltas.resize(base + g.positions.size(), Vec3(0.0f));
            continue;
        }
        const MorphTarget& from = g.targets[t];
        target.positionDeltas.insert(target.positionDeltas.end(), from.positionDeltas.begin(),
                                     from.positionDeltas.end());
        if (!from.normalDeltas.empty()) {
            target.normalDeltas.resize(base, Vec3(0.0f));
            target.normalDeltas.insert(target.normalDeltas.end(), from.normalDeltas.begin(),
                                       from.normalDeltas.end());
        }
    }
}

// Appends one primitive's geometry (a mesh's first primitive's arrays are moved, leaving `g`
// empty); its triangles take slot `slot`, and slot 0 is the first primitive's.
void appendPrimitive(const GltfContext& ctx, PrimitiveGeometry& g, uint32_t slot, Mesh& mesh,
                     std::vector<uint32_t>& slots, const std::string& element) {
    const size_t base = mesh.positions.size(), trianglesBefore = mesh.indices.size() / 3;
    if (g.positions.size() > std::numeric_limits<uint32_t>::max() - base) {
        ctx.fail(element, "more than 2^32 vertices");
    }
    appendMorphDeltas(g, base, mesh);
    // A mesh's first primitive's arrays are moved in, not copied: a 10M-triangle mesh is one
    // primitive, whose copies were a fifth of its load (fresh pages the kernel zeroes).
    const auto append = [](auto& to, auto& from) {
        if (to.empty()) {
            to = std::move(from);
        } else {
            to.insert(to.end(), from.begin(), from.end());
        }
    };
    append(mesh.positions, g.positions);
    append(mesh.normals, g.normals);
    if (!g.uvs.empty()) {
        mesh.uvs.resize(base);  // earlier primitives without TEXCOORD_0 get (0, 0)
        append(mesh.uvs, g.uvs);
    }
    if (!g.tangents.empty()) {
        mesh.tangents.resize(base);  // zero: "derive from the UVs" for primitives without TANGENT
        append(mesh.tangents, g.tangents);
    }
    const size_t triangles = g.indices.size() / 3;
    if (base == 0) {
        append(mesh.indices, g.indices);  // no offset to add
    } else {
        for (uint32_t index : g.indices) mesh.indices.push_back(uint32_t(base) + index);
    }
    // Slots are listed only once a second one exists (a mesh of one slot keeps none): the
    // triangles before it took slot 0.
    if (slot > 0) {
        slots.resize(trianglesBefore, 0u);
        slots.insert(slots.end(), triangles, slot);
    }
}

// The number of morph targets of the glTF mesh. glTF requires every primitive to have the
// same number; a primitive with none is accepted (it is simply not deformed).
size_t morphTargetCount(const GltfContext& ctx, const tinygltf::Mesh& source,
                        const std::string& meshElement) {
    size_t count = 0, first = 0;
    for (size_t p = 0; p < source.primitives.size(); ++p) {
        const size_t n = source.primitives[p].targets.size();
        if (n == 0) continue;
        if (count == 0) {
            count = n;
            first = p;
        } else if (n != count) {
            ctx.fail(meshElement + ".primitives[" + std::to_string(p) + "].targets",
                     std::to_string(n) + " morph targets, but primitives[" + std::to_string(first) +
                         "] has " + std::to_string(count) +
                         " (every primitive of a mesh must have the same number)");
        }
    }
    return count;
}

// extras.targetNames is the de facto convention for naming targets (Blender, three.js);
// a missing or malformed name falls back to "target N".
std::vector<std::string> morphTargetNames(const GltfContext& ctx, const tinygltf::Mesh& source, size_t count,
                                          const std::string& meshElement) {
    std::vector<std::string> names(count);
    for (size_t t = 0; t < count; ++t) names[t] = "target " + std::to_string(t);
    if (!source.extras.IsObject() || !source.extras.Has("targetNames")) return names;
    const tinygltf::Value& given = source.extras.Get("targetNames");
    if (!given.IsArray() || given.ArrayLen() != count) {
        ctx.warn(meshElement + ".extras.targetNames",
                 "expected " + std::to_string(count) + " names; targets named \"target N\"");
        return names;
    }
    for (size_t t = 0; t < count; ++t) {
        const tinygltf::Value& name = given.Get(int(t));
        if (name.IsString() && !name.Get<std::string>().empty()) names[t] = name.Get<std::string>();
    }
    return names;
}

std::vector<float> toFloats(const std::vector<double>& values) {
    return std::vector<float>(values.begin(), values.end());
}

// The glTF mesh's `weights` (checked by finishMorphTargets), zeros when it has none.
std::vector<float> fileMorphWeights(const tinygltf::Mesh& source, size_t count) {
    return source.weights.empty() ? std::vector<float>(count, 0.0f) : toFloats(source.weights);
}

// Moves the imported vertices into the base arrays, names the targets and deforms the mesh
// into the file's default pose (the glTF mesh's weights, else zero).
void finishMorphTargets(const GltfContext& ctx, const tinygltf::Mesh& source, const std::string& meshElement,
                        Mesh& mesh) {
    const size_t count = mesh.morphTargets.size();
    if (!source.weights.empty()) checkGltfNumbers(ctx, source.weights, count, meshElement + ".weights");
    if (count == 0) return;
    const std::vector<std::string> names = morphTargetNames(ctx, source, count, meshElement);
    for (size_t t = 0; t < count; ++t) {
        MorphTarget& target = mesh.morphTargets[t];
        target.name = names[t];
        if (!target.normalDeltas.empty()) target.normalDeltas.resize(mesh.positions.size(), Vec3(0.0f));
    }
    mesh.defaultMorphWeights = fileMorphWeights(source, count);
    mesh.morphWeights = mesh.defaultMorphWeights;
    mesh.basePositions = mesh.positions;
    mesh.baseNormals = mesh.normals;
    applyMorphWeights(mesh);
}

}  // namespace

const std::optional<ImportedMesh>& importGltfMesh(GltfContext& ctx, int meshIndex,
                                                  const std::string& element) {
    if (auto it = ctx.meshes.find(meshIndex); it != ctx.meshes.end()) return it->second;
    const auto& source = gltfElement(ctx, ctx.model().meshes, meshIndex, element, "mesh");
    const std::string meshElement = gltfPath("meshes", size_t(meshIndex));
    Mesh mesh;
    mesh.name = source.name.empty() ? meshElement : source.name;
    mesh.morphTargets.resize(morphTargetCount(ctx, source, meshElement));
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
        if (!g->influences.empty() || !imported.influences.empty()) {
            imported.influences.resize(mesh.positions.size());  // earlier primitives: unweighted
            imported.influences.insert(imported.influences.end(), g->influences.begin(), g->influences.end());
        }
        appendPrimitive(ctx, *g, uint32_t(imported.slotMaterials.size()), mesh, slots, meshElement);
        imported.slotMaterials.push_back(material);
        imported.slotVariantMaterials.push_back(
            gltfPrimitiveVariantMaterials(ctx, size_t(meshIndex), p, ctx.variants.size()));
    }
    if (imported.slotMaterials.empty()) {
        ctx.warn(meshElement, "has no triangles to render; nodes using it are not placed");
        return ctx.meshes[meshIndex] = std::nullopt;
    }
    if (!mesh.uvs.empty()) mesh.uvs.resize(mesh.positions.size());
    if (!mesh.tangents.empty()) mesh.tangents.resize(mesh.positions.size());
    if (!imported.influences.empty()) imported.influences.resize(mesh.positions.size());
    finishMorphTargets(ctx, source, meshElement, mesh);
    mesh.slotCount = uint32_t(imported.slotMaterials.size());
    if (mesh.slotCount > 1) mesh.primitiveSlots = std::move(slots);
    imported.sceneMesh = uint32_t(ctx.scene.meshes.size());
    ctx.scene.meshes.push_back(std::move(mesh));
    return ctx.meshes[meshIndex] = std::move(imported);
}

void poseGltfMeshForNode(GltfContext& ctx, int node, const ImportedMesh& imported, bool firstUse) {
    const auto& n = ctx.model().nodes[size_t(node)];
    const std::string element = gltfPath("nodes", size_t(node));
    Mesh& mesh = ctx.scene.meshes[imported.sceneMesh];
    if (!n.weights.empty()) checkGltfNumbers(ctx, n.weights, mesh.morphTargets.size(), element + ".weights");
    const std::vector<float> wanted =
        n.weights.empty() ? fileMorphWeights(ctx.model().meshes[size_t(n.mesh)], mesh.morphTargets.size())
                          : toFloats(n.weights);
    if (wanted == mesh.defaultMorphWeights) return;
    if (!firstUse) {
        ctx.warn(element, "morph weights differ from those of the earlier node that uses mesh \"" +
                              mesh.name + "\"; its instances share one pose, the earlier node's");
        return;
    }
    mesh.defaultMorphWeights = wanted;
    mesh.morphWeights = wanted;
    applyMorphWeights(mesh);
}

}  // namespace pt
