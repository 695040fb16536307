#include "render/compile/merged_geometry.h"

#include <cstring>
#include <stdexcept>

#include "render/bvh/aabb.h"
#include "render/compile/compile_scene.h"

namespace pt {
namespace {

// Far from the origin for its size, an instance's world-space copies would lose the precision
// that tracing in object space keeps (instance_space.h): a box of side 0.25 at 1e5 leaked
// light through its corners when merged. Up to this ratio of its world position to its size,
// world-space rounding stays within what the spawn offsets allow for.
constexpr float kMaxPositionToSize = 16.0f;

bool nearOriginForItsSize(const Mesh& mesh, const Affine3& objectToWorld) {
    Aabb box;
    for (const Vec3& p : mesh.positions) box.grow(objectToWorld.transformPoint(p));
    const float size = maxComponent(box.hi - box.lo);
    const float position = maxf(maxComponent(vabs(box.lo)), maxComponent(vabs(box.hi)));
    return position <= kMaxPositionToSize * size;
}

// Meshes a rig skins. Like morphed meshes, they move every frame of an animation: merged, each
// frame would bake them again on the host, and a GPU skin (SkinningSite::Device) could not.
std::vector<bool> skinnedMeshes(const Scene& scene) {
    std::vector<bool> skinned(scene.meshes.size(), false);
    for (const AnimationRig& rig : scene.rigs) {
        for (const SkinnedMesh& s : rig.skinnedMeshes) {
            if (s.mesh < skinned.size()) skinned[s.mesh] = true;
        }
    }
    return skinned;
}

// `uses`: the traced instances of each mesh. A mesh copied once per use costs its triangles
// times its uses; past kMaxCopiedTriangles a mesh stays instanced (a forest of one tree).
bool mergeable(const Scene& scene, size_t i, const std::vector<uint32_t>& uses,
               const std::vector<bool>& skinned) {
    if (!isTracedInstance(scene, i)) return false;
    const Instance& instance = scene.instances[i];
    const Mesh& mesh = scene.meshes[instance.mesh];
    const uint64_t copies = uint64_t(mesh.primitiveCount()) * uses[instance.mesh];
    return mesh.kind == GeometryKind::Triangles && mesh.morphTargets.empty() && !skinned[instance.mesh] &&
           mesh.primitiveCount() <= kMaxMergedMeshTriangles &&
           (uses[instance.mesh] == 1 || copies <= kMaxCopiedTriangles) &&
           nearOriginForItsSize(mesh, instance.objectToWorld);
}

// Keeps the per-vertex arrays parallel to positions (the merged BLAS has no normals or UVs:
// shading reads the instance's own mesh).
void padVertexArrays(CompiledScene& out) {
    out.normals.resize(out.positions.size());
    if (!out.uvs.empty()) out.uvs.resize(out.positions.size());
    if (!out.tangents.empty()) out.tangents.resize(out.positions.size());
}

}  // namespace

void planMergedGeometry(const Scene& scene, CompiledScene& out) {
    MergedGeometry merged;
    merged.sceneInstanceMerged.assign(scene.instances.size(), false);
    std::vector<uint32_t> uses(scene.meshes.size(), 0);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        if (isTracedInstance(scene, i)) ++uses[scene.instances[i].mesh];
    }
    const std::vector<bool> skinned = skinnedMeshes(scene);
    uint32_t triangles = 0;
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        if (!mergeable(scene, i, uses, skinned)) continue;
        const uint32_t count = scene.meshes[scene.instances[i].mesh].primitiveCount();
        if (triangles + count > kMaxMergedTriangles) break;
        const uint32_t vertices = uint32_t(scene.meshes[scene.instances[i].mesh].positions.size());
        merged.pieces.push_back({uint32_t(i), scene.instances[i].mesh, 0, triangles, vertices});
        merged.sceneInstanceMerged[i] = true;
        triangles += count;
    }
    if (merged.pieces.size() < 2) {
        out.merged = {};
        return;
    }
    BlasRef blas{};
    blas.kind = GeometryKind::Triangles;
    blas.primitiveOffset = uint32_t(out.triangles.size());
    blas.primitiveCount = triangles;
    merged.blas = uint32_t(out.blases.size());
    out.blases.push_back(blas);
    for (MergedPiece& piece : merged.pieces) {
        const Mesh& mesh = scene.meshes[piece.mesh];
        const uint32_t base = uint32_t(out.positions.size());
        piece.firstVertex = base;
        out.positions.resize(base + mesh.positions.size());
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            out.triangles.push_back(
                {base + mesh.indices[t], base + mesh.indices[t + 1], base + mesh.indices[t + 2]});
        }
    }
    out.triangleSlots.resize(out.triangles.size(), 0u);  // unread: hits map back to the instance's slots
    padVertexArrays(out);
    out.merged = std::move(merged);
}

bool mergedPlanHolds(const Scene& scene, const CompiledScene& out) {
    const MergedGeometry& merged = out.merged;
    if (!merged.active()) return true;
    if (scene.instances.size() != merged.sceneInstanceMerged.size()) return false;
    for (const MergedPiece& piece : merged.pieces) {
        const uint32_t mesh = scene.instances[piece.sceneInstance].mesh;
        if (mesh != piece.mesh || mesh >= scene.meshes.size() ||
            scene.meshes[mesh].positions.size() != piece.vertexCount) {
            return false;
        }
    }
    return true;
}

bool bakeMergedGeometry(const Scene& scene, CompiledScene& out) {
    const MergedGeometry& merged = out.merged;
    out.mergedTriangles.clear();
    if (!merged.active()) return false;
    if (!mergedPlanHolds(scene, out)) {
        throw std::invalid_argument("the instances changed since the merged geometry was planned; recompile");
    }
    bool changed = false;
    out.mergedTriangles.reserve(out.blases[merged.blas].primitiveCount);
    for (const MergedPiece& piece : merged.pieces) {
        const Mesh& mesh = scene.meshes[piece.mesh];
        const Instance& instance = scene.instances[piece.sceneInstance];
        const uint32_t compiled = out.renderInstanceOf[piece.sceneInstance];
        // A hidden instance keeps its place in the arrays (so the BLAS keeps its shape for a
        // refit) as zero-area triangles at one point, which the watertight test never hits.
        const Vec3 collapsed = instance.objectToWorld.translation();
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            const Vec3 world =
                compiled != kNotTraced ? instance.objectToWorld.transformPoint(mesh.positions[v]) : collapsed;
            Vec3& stored = out.positions[piece.firstVertex + v];
            changed |= std::memcmp(&stored, &world, sizeof(Vec3)) != 0;
            stored = world;
        }
        for (uint32_t t = 0; t < mesh.primitiveCount(); ++t) out.mergedTriangles.push_back({compiled, t});
    }
    return changed;
}

}  // namespace pt
