#pragma once
// What a backend does to bring its compiled scene up to date after an edit (issue 16): the
// plan is decided from the edit's delta (its bits and the ids it touched) and the compiled
// scene alone, without a GPU,
// and both backends execute it: the CUDA backend on the device (with refits), the CPU backend
// on the host (a material drag recompiles materials, never a BVH). Steps a plan cannot know in
// advance (a refit that degraded past its threshold, emission that changed with a material)
// are decided where they are executed, from the helpers below.
#include <vector>

#include "render/backend/backend.h"
#include "render/compile/compile_scene.h"
#include "render/scene/scene_changes.h"
#include "render/util/stopwatch.h"

namespace pt {

struct SyncPlan {
    // Everything from the scene: no compiled scene yet, new meshes or textures, or instances
    // the merged BLAS no longer holds (merged_geometry.h).
    bool fullBuild = false;
    bool refitGeometry = false;  // vertex positions moved: refit their BLASes ...
    TouchedIds meshes;           // ... of these meshes (compared, where the edit did not say)
    bool instances = false;      // transforms or visibility: compileInstances, then the TLAS
    bool materials = false;      // these materials; then the light table where emission changed
    TouchedIds materialIds;
    bool lights = false;       // the light table (environment or punctual lights edited)
    bool environment = false;  // ... and the environment's sampling tables
    bool reset = false;        // accumulation restarts (everything but display changes)
};

SyncPlan planSync(const CompiledScene* compiled, const Scene& scene, const SceneDelta& changes);

// Copies the scene's edited materials into the compiled scene: those `edited` names, or all
// of them where it does not say or the count changed (`all` is then set).
struct MaterialsUpdate {
    bool all = false;
    std::vector<uint32_t> copied;  // where !all
    bool emissionChanged = false;  // which surfaces emit, or how much: the light table follows
};
MaterialsUpdate updateEditedMaterials(const Scene& scene, CompiledScene& compiled, const TouchedIds& edited);

// What sync did, ranked: the report names the most expensive (SyncReport::action).
enum class SyncAction { Nothing, Reset, Lights, Materials, Tlas, Refit, Rebuild, FullBuild };
const char* syncActionName(SyncAction action);

// Keeps the most expensive action seen.
struct SyncActions {
    SyncAction most = SyncAction::Nothing;
    void add(SyncAction a) {
        if (a > most) most = a;
    }
};

// Runs `step` on the host, appends what it cost to the report, and returns it (seconds).
template <class Step>
double timedHostStep(SyncReport& report, const char* name, Step&& step) {
    const auto start = Clock::now();
    step();
    report.steps.push_back({name, secondsSince(start)});
    return report.steps.back().seconds;
}

}  // namespace pt
