#pragma once
// Posing a Scene's rigs (render/animation/rig.h) at a time of one of their animations: the
// nodes' poses from the animation's channels (or the rest pose), their global transforms, then
// the instances they place, the morph weights of their meshes and the skinned meshes'
// vertices. What moved comes back as a delta naming those instances and meshes, so a backend
// refits exactly those BLASes and rebuilds the TLAS (DESIGN.md, "Data flow").
#include <cstdint>
#include <string>
#include <vector>

#include "render/scene/scene.h"
#include "render/scene/scene_changes.h"

namespace pt {

// Where a pose's skinned vertices are computed. Host: into the Scene's meshes, which every
// backend reads. Device: by a backend that skins on its device (BackendCapabilities::
// skinsOnDevice), from the joint matrices the pose keeps with each skinned mesh
// (SkinnedMesh::pendingJoints), so a frame costs the host its joints, not its vertices; the
// Scene's vertices of those meshes then lag until skinPendingOnHost. Meshes that are morphed
// as well as skinned are always skinned on the host.
enum class SkinningSite { Host, Device };

// Poses scene.rigs[rig] at `time` (seconds) of animation `animation` (-1: the rest pose, no
// animation). Instances or meshes the rig names that no longer fit it (an edit removed them)
// are left alone. Throws std::invalid_argument for an animation index out of range or a rig
// whose data contradicts itself (a channel naming a missing node, a cycle).
SceneDelta poseRig(Scene& scene, uint32_t rig, int32_t animation, float time,
                   SkinningSite site = SkinningSite::Host);

// Which animation each rig plays, for a choice by name or by index (a whole number), or ""
// for each rig's first: -1 (the rest pose) for a rig without it. Throws std::invalid_argument
// where the scene has no animation, or no rig has the one asked for (listing those there are).
std::vector<int32_t> chooseAnimations(const Scene& scene, const std::string& which);

// Poses every rig at `time` of its chosen animation; what moved, merged.
SceneDelta poseAnimations(Scene& scene, const std::vector<int32_t>& chosen, float time,
                          SkinningSite site = SkinningSite::Host);

// The skinned mesh whose joints a device pose left pending for Scene mesh `mesh`, or null
// (none, or its vertices on the host are current).
const SkinnedMesh* pendingSkinOf(const Scene& scene, uint32_t mesh);

// Skins on the host every mesh a device pose left pending, so the Scene's vertices show the
// current pose (before a backend that reads them takes over, or a host reader); returns
// those meshes. A backend that skinned them on its device already shows the same vertices.
std::vector<uint32_t> skinPendingOnHost(Scene& scene);

}  // namespace pt
