#include "render/backend/sync_plan.h"

#include <cstring>

namespace pt {

SyncPlan planSync(const CompiledScene* compiled, const Scene& scene, const SceneDelta& changes) {
    SyncPlan plan;
    plan.reset = changes.mask != SceneChanges::Display;
    plan.fullBuild = !compiled || changes.has(SceneChanges::Topology | SceneChanges::Textures) ||
                     (changes.has(SceneChanges::Transforms) && !mergedPlanHolds(scene, *compiled));
    if (plan.fullBuild) return plan;
    plan.refitGeometry = changes.has(SceneChanges::Geometry);
    if (plan.refitGeometry) plan.meshes = changes.meshes;
    plan.instances = changes.has(SceneChanges::Transforms);
    plan.materials = changes.has(SceneChanges::Materials);
    if (plan.materials) plan.materialIds = changes.materials;
    plan.environment = changes.has(SceneChanges::Environment);
    plan.lights = plan.environment || changes.has(SceneChanges::Lights);
    return plan;
}

namespace {

bool sameEmission(const Material& a, const Material& b) {
    const Vec3 ea = a.emittedRadiance(), eb = b.emittedRadiance();
    return std::memcmp(&ea, &eb, sizeof(Vec3)) == 0 && a.emissiveTexture.texture == b.emissiveTexture.texture;
}

}  // namespace

MaterialsUpdate updateEditedMaterials(const Scene& scene, CompiledScene& compiled, const TouchedIds& edited) {
    MaterialsUpdate update;
    // compileMaterials appends one fallback material for unmapped slots.
    update.all = edited.every || compiled.materials.size() != scene.materials.size() + 1;
    if (update.all) {
        std::vector<Material> materials = compileMaterials(scene);
        update.emissionChanged = materials.size() != compiled.materials.size();
        for (size_t i = 0; i < materials.size() && !update.emissionChanged; ++i) {
            update.emissionChanged = !sameEmission(compiled.materials[i], materials[i]);
        }
        compiled.materials = std::move(materials);
    } else {
        update.copied = edited.below(uint32_t(scene.materials.size()));
        for (const uint32_t i : update.copied) {
            update.emissionChanged |= !sameEmission(compiled.materials[i], scene.materials[i].params);
            compiled.materials[i] = scene.materials[i].params;
        }
    }
    updateTransparency(compiled);
    return update;
}

const char* syncActionName(SyncAction action) {
    switch (action) {
        case SyncAction::Nothing: return "nothing";
        case SyncAction::Reset: return "reset";
        case SyncAction::Lights: return "lights";
        case SyncAction::Materials: return "materials";
        case SyncAction::Tlas: return "TLAS";
        case SyncAction::Refit: return "refit";
        case SyncAction::Rebuild: return "rebuild";
        case SyncAction::FullBuild: return "full build";
    }
    return "nothing";
}

}  // namespace pt
