#pragma once
// The bench's syncs outside the timing of syncs themselves: a sync, then whatever the backend
// left running behind its first frame (the CUDA backend's host SAH builds of large meshes,
// IntegratorToggles::gpuFirstBuild), so rates are measured on the trees a render settles on,
// and no build competes with them for the host.
#include "render/backend/backend.h"

namespace pt {

inline void syncSettled(Backend& backend, const Scene& scene, const SceneDelta& changes) {
    backend.sync(scene, changes, {});
    backend.finishBackgroundWork();
}

}  // namespace pt
