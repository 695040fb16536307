#pragma once
// What a model file brings for animation, kept with the Scene so that it can be posed at any
// time (glTF 2.0 skins and animations, issue 19): the file's node hierarchy with each node's
// rest pose, the instances its nodes placed, the animations, the skins, and the skinned
// meshes with their bind-pose vertices. render/scene/scene_animation.h poses it.
#include <cstdint>
#include <string>
#include <vector>

#include "render/animation/keyframes.h"
#include "render/animation/skinning.h"

namespace pt {

// A Scene instance a node placed: its transform is the object's, times the node's global
// transform, times `extra` (an EXT_mesh_gpu_instancing instance's own).
struct RigInstance {
    uint32_t node = 0;
    uint32_t instance = 0;  // Scene::instances index
    Affine3 extra;
};

// A mesh deformed by a skin. Each skinned node has a Scene mesh of its own (two nodes skinning
// one glTF mesh differently need two sets of vertices).
struct SkinnedMesh {
    uint32_t mesh = 0;  // Scene::meshes index
    uint32_t skin = 0;  // AnimationRig::skins index
    uint32_t node = 0;  // the node that places it
    // The bind pose (unused where the mesh has morph targets: the morphed vertices are).
    std::vector<Vec3> bindPositions, bindNormals;
    std::vector<Vec4> bindTangents;
    std::vector<JointInfluences> influences;  // parallel to the positions, normalised
    // The joint matrices of a pose left to a backend that skins on its device
    // (SkinningSite::Device, render/scene/scene_animation.h): the Scene mesh's vertices then
    // show an earlier pose until skinPendingOnHost. Empty once the host vertices are current.
    std::vector<Affine3> pendingJoints;
};

// A node whose mesh has morph targets: weight channels of the node drive that mesh.
struct MorphedNode {
    uint32_t node = 0;
    uint32_t mesh = 0;  // Scene::meshes index
};

struct AnimationRig {
    int32_t object = -1;              // the SceneObject that placed the file
    std::vector<int32_t> parents;     // per file node; -1 for a root
    std::vector<NodePose> restPoses;  // per file node, as the file gives it
    std::vector<Animation> animations;
    std::vector<Skin> skins;
    std::vector<RigInstance> instances;
    std::vector<SkinnedMesh> skinnedMeshes;
    std::vector<MorphedNode> morphedNodes;
};

}  // namespace pt
