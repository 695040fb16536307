#include "render/scene/scene_animation.h"

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "render/scene/morph.h"

namespace pt {
namespace {

// Skins `skinned` in its node's space at joint matrices `joints`; a mesh with morph targets is
// morphed first, as glTF orders them, and skinned from its morphed vertices.
void skinOnHost(SkinnedMesh& skinned, const std::vector<Affine3>& joints, Mesh& mesh) {
    skinned.pendingJoints.clear();
    if (mesh.morphTargets.empty()) {
        skinVertices(joints,
                     {skinned.bindPositions, skinned.bindNormals, skinned.bindTangents, skinned.influences},
                     mesh.positions, mesh.normals, mesh.tangents);
        return;
    }
    applyMorphWeights(mesh);
    const std::vector<Vec3> positions = mesh.positions, normals = mesh.normals;
    skinVertices(joints, {positions, normals, skinned.bindTangents, skinned.influences}, mesh.positions,
                 mesh.normals, mesh.tangents);
}

// Whether `skinned` still deforms Scene mesh `mesh` as imported (an edit may have replaced it).
bool stillSkins(const SkinnedMesh& skinned, const AnimationRig& rig, const Scene& scene) {
    return skinned.mesh < scene.meshes.size() && skinned.skin < rig.skins.size() &&
           scene.meshes[skinned.mesh].positions.size() == skinned.influences.size();
}

}  // namespace

SceneDelta poseRig(Scene& scene, uint32_t rigIndex, int32_t animation, float time, SkinningSite site) {
    if (rigIndex >= scene.rigs.size())
        throw std::invalid_argument("rig " + std::to_string(rigIndex) + " does not exist");
    AnimationRig& rig = scene.rigs[rigIndex];
    if (animation >= int32_t(rig.animations.size())) {
        throw std::invalid_argument("animation " + std::to_string(animation) + " does not exist (" +
                                    std::to_string(rig.animations.size()) + " in the file)");
    }
    std::vector<NodePose> poses = rig.restPoses;
    if (animation >= 0) applyAnimation(rig.animations[size_t(animation)], time, poses);
    const std::vector<Affine3> globals = globalTransforms(rig.parents, poses);
    const bool objectExists = rig.object >= 0 && size_t(rig.object) < scene.objects.size();
    const Affine3 objectToWorld =
        objectExists ? scene.objects[size_t(rig.object)].transform.toAffine() : Affine3{};

    std::vector<uint32_t> movedInstances, movedMeshes;
    for (const RigInstance& placed : rig.instances) {
        if (placed.instance >= scene.instances.size() || placed.node >= globals.size()) continue;
        Instance& instance = scene.instances[placed.instance];
        if (instance.object != rig.object) continue;  // the instance list changed since import
        const Affine3 transform = objectToWorld * globals[placed.node] * placed.extra;
        if (std::memcmp(&transform, &instance.objectToWorld, sizeof(Affine3)) == 0) continue;
        instance.objectToWorld = transform;
        movedInstances.push_back(placed.instance);
    }
    std::vector<bool> skinnedMesh(scene.meshes.size(), false);
    for (const SkinnedMesh& s : rig.skinnedMeshes) {
        if (s.mesh < skinnedMesh.size()) skinnedMesh[s.mesh] = true;
    }
    for (const MorphedNode& morphed : rig.morphedNodes) {
        if (morphed.mesh >= scene.meshes.size() || morphed.node >= poses.size()) continue;
        Mesh& mesh = scene.meshes[morphed.mesh];
        const std::vector<float>& weights = poses[morphed.node].weights;
        if (weights.size() != mesh.morphTargets.size() || weights == mesh.morphWeights) continue;
        mesh.morphWeights = weights;
        if (!skinnedMesh[morphed.mesh]) applyMorphWeights(mesh);  // else morphed as it is skinned
        movedMeshes.push_back(morphed.mesh);
    }
    for (SkinnedMesh& skinned : rig.skinnedMeshes) {
        if (!stillSkins(skinned, rig, scene) || skinned.node >= globals.size()) continue;
        Mesh& mesh = scene.meshes[skinned.mesh];
        std::vector<Affine3> joints = jointMatrices(rig.skins[skinned.skin], globals, globals[skinned.node]);
        if (site == SkinningSite::Device && mesh.morphTargets.empty()) {
            skinned.pendingJoints = std::move(joints);
        } else {
            skinOnHost(skinned, joints, mesh);
        }
        movedMeshes.push_back(skinned.mesh);
    }
    SceneDelta delta;
    if (!movedInstances.empty()) delta |= instancesMoved(movedInstances);
    if (!movedMeshes.empty()) delta |= meshesMoved(movedMeshes);
    return delta;
}

std::vector<int32_t> chooseAnimations(const Scene& scene, const std::string& which) {
    std::vector<int32_t> chosen(scene.rigs.size(), -1);
    std::string names;
    bool found = false;
    char* end = nullptr;
    const long index = std::strtol(which.c_str(), &end, 10);
    const bool byIndex = !which.empty() && *end == '\0';
    for (size_t r = 0; r < scene.rigs.size(); ++r) {
        const std::vector<Animation>& animations = scene.rigs[r].animations;
        for (size_t a = 0; a < animations.size(); ++a) {
            names += (names.empty() ? "" : ", ") + std::to_string(a) + " \"" + animations[a].name + "\"";
            const bool match = which.empty() ? a == 0
                               : byIndex     ? long(a) == index
                                             : animations[a].name == which;
            if (match && chosen[r] < 0) {
                chosen[r] = int32_t(a);
                found = true;
            }
        }
    }
    if (names.empty()) throw std::invalid_argument("the scene has no animation");
    if (!found) throw std::invalid_argument("no animation \"" + which + "\" (the scene has " + names + ")");
    return chosen;
}

SceneDelta poseAnimations(Scene& scene, const std::vector<int32_t>& chosen, float time, SkinningSite site) {
    SceneDelta delta;
    for (size_t r = 0; r < scene.rigs.size() && r < chosen.size(); ++r)
        delta |= poseRig(scene, uint32_t(r), chosen[r], time, site);
    return delta;
}

const SkinnedMesh* pendingSkinOf(const Scene& scene, uint32_t mesh) {
    for (const AnimationRig& rig : scene.rigs) {
        for (const SkinnedMesh& skinned : rig.skinnedMeshes) {
            if (skinned.mesh == mesh && !skinned.pendingJoints.empty() && stillSkins(skinned, rig, scene))
                return &skinned;
        }
    }
    return nullptr;
}

std::vector<uint32_t> skinPendingOnHost(Scene& scene) {
    std::vector<uint32_t> skinnedMeshes;
    for (AnimationRig& rig : scene.rigs) {
        for (SkinnedMesh& skinned : rig.skinnedMeshes) {
            if (skinned.pendingJoints.empty()) continue;
            if (stillSkins(skinned, rig, scene)) {
                const std::vector<Affine3> joints = std::move(skinned.pendingJoints);
                skinOnHost(skinned, joints, scene.meshes[skinned.mesh]);
                skinnedMeshes.push_back(skinned.mesh);
            }
            skinned.pendingJoints.clear();
        }
    }
    return skinnedMeshes;
}

}  // namespace pt
