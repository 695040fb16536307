#pragma once
// The toggles as a list of named states, the form stats, the CLI and the editor report them in,
// one per row of the toggle table (render/backend/toggle_table.h), named by its keys.
#include <string>
#include <vector>

#include "render/backend/backend.h"
#include "render/kernel/render_scene.h"

namespace pt {

// Every toggle with requested = active = its value; backends then mark what they cannot apply.
std::vector<ToggleState> integratorToggleStates(const IntegratorToggles& toggles);

// The integrator's switches (NEE, MIS, roulette, clamp, pixel jitter) into the settings kernels
// read; the same on every backend.
void applyIntegratorToggles(const IntegratorToggles& toggles, IntegratorSettings& settings);

}  // namespace pt
