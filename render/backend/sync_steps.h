#pragma once
// Executing a sync plan (sync_plan.h): the order of the steps and what each implies for the
// next (moved geometry or instances need a new TLAS and, where the backend says, a new light
// table; a step that cannot be done in place falls back to a full build) are written once,
// here; each backend says how a step is done, on the host or on its device.
#include "render/backend/sync_plan.h"

namespace pt {

class SyncSteps {
public:
    virtual ~SyncSteps() = default;
    // Moved vertices: refits the BLASes of the meshes that changed among `meshes` (or
    // rebuilds them, adding what it did to `actions`); *moved says whether any did. False
    // where only a full build will do (a topology edit, a refit past the SAH drift threshold
    // where the backend cannot rebuild one BLAS).
    virtual bool refitMeshes(const Scene& scene, const TouchedIds& meshes, SyncReport& report,
                             SyncActions& actions, bool* moved) = 0;
    // Copies the edited materials; returns whether emission changed (the light table follows).
    virtual bool updateMaterials(const Scene& scene, const TouchedIds& materials, SyncReport& report) = 0;
    // Transforms and visibility: the instance list (and the merged BLAS's copies, refitted);
    // *countChanged says whether the list changed length. False where only a full build will do.
    virtual bool updateInstances(const Scene& scene, SyncReport& report, SyncActions& actions,
                                 bool* countChanged) = 0;
    // Whether the light table is rebuilt after geometry or instances moved (emitters name
    // instances, their weights follow their areas and the scene's bounds).
    virtual bool lightsFollowMoves(bool instanceCountChanged) const = 0;
    virtual void buildTlas(SyncReport& report) = 0;
    virtual void updateLights(const Scene& scene, bool environment, SyncReport& report) = 0;
    virtual void fullBuild(const Scene& scene, const ProgressFn& progress, SyncReport& report) = 0;
};

// Runs `plan`'s steps through `steps`; returns the most expensive action done.
SyncAction executeSyncPlan(const SyncPlan& plan, const Scene& scene, SyncSteps& steps, SyncReport& report,
                           const ProgressFn& progress);

}  // namespace pt
