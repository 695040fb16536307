#include "render/backend/toggle_states.h"

namespace pt {

std::vector<ToggleState> integratorToggleStates(const IntegratorToggles& t) {
    const auto state = [](const char* name, bool on) { return ToggleState{name, on, on, ""}; };
    return {
        state("nee", t.nextEventEstimation),
        state("mis", t.multipleImportance),
        state("rr", t.russianRoulette),
        // "bvh" is on when the BVH is used, i.e. when brute force is off.
        state("bvh", !t.bruteForce),
        state("merge_instances", t.mergeInstances),
        state("pixel_jitter", t.pixelJitter),
        state("auto_schedule", t.autoSchedule),
        state("megakernel", t.megakernel),
        state("path_regeneration", t.pathRegeneration),
        state("compaction", t.streamCompaction),
        state("material_sort", t.materialSort),
        state("first_hit_cache", t.firstHitCache),
    };
}

void applyIntegratorToggles(const IntegratorToggles& t, IntegratorSettings& s) {
    s.nextEventEstimation = t.nextEventEstimation ? 1u : 0u;
    s.multipleImportance = t.multipleImportance ? 1u : 0u;
    s.russianRoulette = t.russianRoulette ? 1u : 0u;
    s.clampRadiance = t.clampRadiance;
    s.pixelJitter = t.pixelJitter ? 1u : 0u;
}

bool isGpuSchedulingToggle(const std::string& name) {
    return name == "auto_schedule" || name == "megakernel" || name == "path_regeneration" ||
           name == "compaction" || name == "material_sort" || name == "first_hit_cache";
}

}  // namespace pt
