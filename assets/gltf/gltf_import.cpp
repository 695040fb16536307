// importGltf: the stages of a glTF import in order. Reading and checking the file lives in
// gltf_document / gltf_json_check, accessors in gltf_accessors, geometry in gltf_primitive /
// gltf_mesh, materials and textures in gltf_materials / gltf_textures, the node hierarchy
// and camera in gltf_nodes, punctual lights in gltf_lights.
#include <cmath>
#include <map>
#include <set>

#include "assets/gltf/gltf_animation.h"
#include "assets/gltf/gltf_document.h"
#include "assets/gltf/gltf_draco.h"
#include "assets/gltf/gltf_instancing.h"
#include "assets/gltf/gltf_lights.h"
#include "assets/gltf/gltf_materials.h"
#include "assets/gltf/gltf_mesh.h"
#include "assets/gltf/gltf_meshopt.h"
#include "assets/gltf/gltf_nodes.h"
#include "assets/gltf/gltf_textures.h"
#include "assets/gltf/gltf_variants.h"
#include "assets/model_import.h"
#include "assets/scene_append_guard.h"

namespace pt {
namespace {

// Extensions whose data this importer reads (KHR_mesh_quantization: the accessor reader
// converts every component type).
const std::set<std::string> kSupportedExtensions = {
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_materials_clearcoat",
    "KHR_materials_specular",
    "KHR_texture_transform",
    "KHR_mesh_quantization",
    "KHR_lights_punctual",
    "KHR_materials_variants",
    "KHR_materials_unlit",
    "KHR_materials_diffuse_transmission",
    "KHR_materials_sheen",
    "KHR_materials_anisotropy",
    "KHR_materials_iridescence",
    "KHR_materials_dispersion",
    "KHR_materials_volume_scatter",
    "EXT_mesh_gpu_instancing",
};

// One warning per unsupported extension the file declares, and per feature it uses that is
// ignored; loading goes on, required or not, so the user sees what can be shown.
void warnAboutUnsupported(const GltfContext& ctx) {
    const auto& model = ctx.model();
    std::set<std::string> reported;
    auto report = [&](const std::string& name, bool required) {
        const bool decoded = (name == kDracoExtension && gltfDracoAvailable()) ||
                             (name == kMeshoptExtension && gltfMeshoptAvailable()) ||
                             (name == kWebpExtension && gltfWebpAvailable());
        const bool honoured = kSupportedExtensions.count(name) || decoded;
        ctx.scene.gltfExtensions[name] = honoured;
        if (honoured || !reported.insert(name).second) return;
        std::string what = (required ? "required extension " : "extension ") + name + " is not supported";
        what += required ? "; loading without it, parts may be missing" : "; ignored";
        ctx.warn("", what);
    };
    for (const std::string& name : model.extensionsRequired) report(name, true);
    for (const std::string& name : model.extensionsUsed) report(name, false);
}

// Per variant, the Scene material of each slot of `mesh` (`defaults` where the variant maps
// none); empty when no variant maps any slot.
std::vector<std::vector<uint32_t>> placedVariantMaterials(GltfContext& ctx, const ImportedMesh& mesh,
                                                          const std::vector<uint32_t>& defaults,
                                                          const std::string& element) {
    bool mapped = false;
    for (const auto& slot : mesh.slotVariantMaterials) {
        for (int material : slot) mapped |= material != kUnmappedVariant;
    }
    if (!mapped) return {};
    std::vector<std::vector<uint32_t>> rows(ctx.variants.size(), defaults);
    for (size_t slot = 0; slot < mesh.slotVariantMaterials.size(); ++slot) {
        for (size_t variant = 0; variant < rows.size(); ++variant) {
            const int material = mesh.slotVariantMaterials[slot][variant];
            if (material != kUnmappedVariant)
                rows[variant][slot] = importGltfMaterial(ctx, material, element);
        }
    }
    return rows;
}

// The placement of `visit`'s mesh, or nullopt (with a warning) when it cannot be drawn.
std::optional<Placement> placeNode(GltfContext& ctx, const GltfNodeVisit& visit, const ImportedMesh& mesh) {
    const auto& node = ctx.model().nodes[size_t(visit.node)];
    const std::string element = gltfPath("nodes", size_t(visit.node));
    if (!isFinite(visit.world)) ctx.fail(element, "world transform is not finite");
    if (visit.world.determinant() == 0.0f) {
        // A zero scale hides a node (animations do this); it has no inverse to trace with.
        ctx.warn(element, "transform has zero scale; not placed");
        return std::nullopt;
    }
    Placement placement;
    placement.name = node.name.empty() ? element : node.name;
    placement.node = visit.node;
    placement.mesh = mesh.sceneMesh;
    placement.fileToNode = visit.world;  // a negative determinant flips winding downstream
    for (int material : mesh.slotMaterials) {
        placement.materials.push_back(importGltfMaterial(ctx, material, element + ".mesh"));
    }
    placement.variantMaterials = placedVariantMaterials(ctx, mesh, placement.materials, element + ".mesh");
    return placement;
}

// The placements of `visit`'s mesh: one, or one per EXT_mesh_gpu_instancing instance (named
// "<node> #i"), each under the node's transform. Instances of zero scale (hidden) are left out
// with one warning for all of them.
void placeNodeInstances(GltfContext& ctx, const GltfNodeVisit& visit, const ImportedMesh& mesh,
                        std::vector<Placement>& placements) {
    const std::vector<Affine3> instances = gltfInstanceTransforms(ctx, visit.node);
    if (instances.empty()) {
        if (auto placement = placeNode(ctx, visit, mesh)) placements.push_back(std::move(*placement));
        return;
    }
    size_t hidden = 0;
    for (size_t i = 0; i < instances.size(); ++i) {
        GltfNodeVisit instance = visit;
        instance.world = visit.world * instances[i];
        if (instance.world.determinant() == 0.0f) {
            ++hidden;
            continue;
        }
        if (auto placement = placeNode(ctx, instance, mesh)) {
            placement->name += " #" + std::to_string(i);
            placement->extra = instances[i];
            placements.push_back(std::move(*placement));
        }
    }
    if (hidden > 0) {
        ctx.warn(gltfPath("nodes", size_t(visit.node)),
                 std::to_string(hidden) + " of " + std::to_string(instances.size()) +
                     " EXT_mesh_gpu_instancing instances have zero scale; not placed");
    }
}

// Skins `node`'s mesh: a skinned node deforms vertices of its own, so a glTF mesh other nodes
// also place is copied for it (`placed` then names the copy).
void skinNode(GltfContext& ctx, int node, size_t meshUses, AnimationRig& rig, ImportedMesh& placed) {
    if (placed.influences.empty()) {
        gltfSkinnedMesh(ctx, rig, node, placed, placed.sceneMesh);  // warns, and checks the skin index
        return;
    }
    if (meshUses > 1) {
        placed.sceneMesh = uint32_t(ctx.scene.meshes.size());
        ctx.scene.meshes.push_back(
            ctx.scene.meshes[ctx.meshes[ctx.model().nodes[size_t(node)].mesh]->sceneMesh]);
    }
    if (std::optional<SkinnedMesh> skinned = gltfSkinnedMesh(ctx, rig, node, placed, placed.sceneMesh))
        rig.skinnedMeshes.push_back(std::move(*skinned));
}

}  // namespace

ImportedFile importGltf(const std::string& path, int32_t object, Scene& scene, const ProgressFn& progress) {
    reportProgress(progress, "load glTF", 0.0);
    SceneAppendGuard guard(scene);
    const GltfDocument doc = loadGltfDocument(path);
    GltfContext ctx{doc, scene, object, {}, {}, {}, {}, {}, {}, {}, {}};
    warnAboutUnsupported(ctx);
    ctx.variants = gltfVariantNames(ctx);
    const std::vector<GltfNodeVisit> visits = walkGltfScene(ctx);

    ImportedFile file;
    file.camera = gltfCamera(ctx, visits);
    file.lights = gltfLights(ctx, visits);
    file.variants = ctx.variants;
    file.rig = readGltfRig(ctx);
    std::set<uint32_t> posedMeshes;  // Scene meshes whose first node has set their morph pose
    std::map<int, size_t> meshUses;  // glTF mesh -> the nodes that place it
    size_t meshNodes = 0, done = 0;
    for (const GltfNodeVisit& visit : visits) {
        const int mesh = doc.model.nodes[size_t(visit.node)].mesh;
        meshNodes += mesh >= 0;
        if (mesh >= 0) ++meshUses[mesh];
    }
    for (const GltfNodeVisit& visit : visits) {
        const int mesh = doc.model.nodes[size_t(visit.node)].mesh;
        if (mesh < 0) continue;
        const std::string node = gltfPath("nodes", size_t(visit.node));
        const auto& imported = importGltfMesh(ctx, mesh, node);
        reportProgress(progress, "load glTF", double(++done) / double(meshNodes));
        if (!imported) continue;
        poseGltfMeshForNode(ctx, visit.node, *imported, posedMeshes.insert(imported->sceneMesh).second);
        ImportedMesh placed = *imported;
        if (file.rig && doc.model.nodes[size_t(visit.node)].skin >= 0)
            skinNode(ctx, visit.node, meshUses[mesh], *file.rig, placed);
        placeNodeInstances(ctx, visit, placed, file.placements);
    }
    if (file.rig) addGltfMorphedNodes(ctx, *file.rig);
    reportProgress(progress, "load glTF", 1.0);
    guard.commit();
    return file;
}

}  // namespace pt
