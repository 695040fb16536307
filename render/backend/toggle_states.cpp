#include "render/backend/toggle_states.h"

namespace pt {

std::vector<ToggleState> integratorToggleStates(const IntegratorToggles& t) {
    std::vector<ToggleState> states;
    for (const ToggleRow& row : toggleTable()) {
        const bool on = row.get(t);
        states.push_back({row.id, row.key, on, on, ""});
    }
    return states;
}

void applyIntegratorToggles(const IntegratorToggles& t, IntegratorSettings& s) {
    s.nextEventEstimation = t.nextEventEstimation ? 1u : 0u;
    s.multipleImportance = t.multipleImportance ? 1u : 0u;
    s.russianRoulette = t.russianRoulette ? 1u : 0u;
    s.clampRadiance = t.clampRadiance;
    s.pixelJitter = t.pixelJitter ? 1u : 0u;
}

}  // namespace pt
