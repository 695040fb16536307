#include "render/backend/sync_plan.h"

#include <cstring>

namespace pt {

SyncPlan planSync(const CompiledScene* compiled, const Scene& scene, SceneChangeMask changes) {
    SyncPlan plan;
    plan.reset = changes != SceneChanges::Display;
    plan.fullBuild = !compiled || (changes & (SceneChanges::Topology | SceneChanges::Textures)) ||
                     ((changes & SceneChanges::Transforms) && !mergedPlanHolds(scene, *compiled));
    if (plan.fullBuild) return plan;
    plan.refitGeometry = (changes & SceneChanges::Geometry) != 0;
    plan.instances = (changes & SceneChanges::Transforms) != 0;
    plan.materials = (changes & SceneChanges::Materials) != 0;
    plan.environment = (changes & SceneChanges::Environment) != 0;
    plan.lights = plan.environment || (changes & SceneChanges::Lights);
    return plan;
}

bool emissionChanged(const std::vector<Material>& before, const std::vector<Material>& after) {
    if (before.size() != after.size()) return true;
    for (size_t i = 0; i < before.size(); ++i) {
        const Vec3 a = before[i].emittedRadiance(), b = after[i].emittedRadiance();
        if (std::memcmp(&a, &b, sizeof(Vec3)) != 0 ||
            before[i].emissiveTexture.texture != after[i].emissiveTexture.texture) {
            return true;
        }
    }
    return false;
}

const char* syncActionName(SyncAction action) {
    switch (action) {
        case SyncAction::Nothing:
            return "nothing";
        case SyncAction::Reset:
            return "reset";
        case SyncAction::Lights:
            return "lights";
        case SyncAction::Materials:
            return "materials";
        case SyncAction::Tlas:
            return "TLAS";
        case SyncAction::Refit:
            return "refit";
        case SyncAction::Rebuild:
            return "rebuild";
        case SyncAction::FullBuild:
            return "full build";
    }
    return "nothing";
}

}  // namespace pt
