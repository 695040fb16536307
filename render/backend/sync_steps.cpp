#include "render/backend/sync_steps.h"

namespace pt {

SyncAction executeSyncPlan(const SyncPlan& plan, const Scene& scene, SyncSteps& steps, SyncReport& report,
                           const ProgressFn& progress) {
    SyncActions actions;
    if (plan.reset) actions.add(SyncAction::Reset);
    bool full = plan.fullBuild, tlas = false, lights = plan.lights;
    if (!full && plan.refitGeometry) {
        bool moved = false;
        full = !steps.refitMeshes(scene, plan.meshes, report, actions, &moved);
        if (moved) {
            tlas = true;  // the instances' world boxes moved
            lights |= steps.lightsFollowMoves(false);
        }
    }
    // Materials before instances: an instance may name a material the edit added.
    if (!full && plan.materials) {
        lights |= steps.updateMaterials(scene, plan.materialIds, report);
        actions.add(SyncAction::Materials);
    }
    if (!full && plan.instances) {
        bool countChanged = false;
        full = !steps.updateInstances(scene, report, actions, &countChanged);
        tlas = true;
        lights |= steps.lightsFollowMoves(countChanged);
    }
    if (full) {
        steps.fullBuild(scene, progress, report);
        actions.add(SyncAction::FullBuild);
        return actions.most;
    }
    if (tlas) {
        steps.buildTlas(report);
        actions.add(SyncAction::Tlas);
    }
    if (lights) {
        steps.updateLights(scene, plan.environment, report);
        actions.add(SyncAction::Lights);
    }
    return actions.most;
}

}  // namespace pt
