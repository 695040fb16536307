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

// Poses scene.rigs[rig] at `time` (seconds) of animation `animation` (-1: the rest pose, no
// animation). Instances or meshes the rig names that no longer fit it (an edit removed them)
// are left alone. Throws std::invalid_argument for an animation index out of range or a rig
// whose data contradicts itself (a channel naming a missing node, a cycle).
SceneDelta poseRig(Scene& scene, uint32_t rig, int32_t animation, float time);

// Which animation each rig plays, for a choice by name or by index (a whole number), or ""
// for each rig's first: -1 (the rest pose) for a rig without it. Throws std::invalid_argument
// where the scene has no animation, or no rig has the one asked for (listing those there are).
std::vector<int32_t> chooseAnimations(const Scene& scene, const std::string& which);

// Poses every rig at `time` of its chosen animation; what moved, merged.
SceneDelta poseAnimations(Scene& scene, const std::vector<int32_t>& chosen, float time);

}  // namespace pt
