#pragma once
// The toggles as a list of named states, the form stats, the CLI and the editor report them in.
// Names are the CLI's: nee, mis, rr, bvh, pixel_jitter, megakernel, compaction, material_sort,
// first_hit_cache.
#include <string>
#include <vector>

#include "render/backend/backend.h"
#include "render/scene/render_scene.h"

namespace pt {

// Every toggle with requested = active = its value; backends then mark what they cannot apply.
std::vector<ToggleState> integratorToggleStates(const IntegratorToggles& toggles);

// The integrator's switches (NEE, MIS, roulette, clamp, pixel jitter) into the settings kernels
// read; the same on every backend.
void applyIntegratorToggles(const IntegratorToggles& toggles, IntegratorSettings& settings);

// megakernel, compaction, material_sort, first_hit_cache: scheduling choices of the CUDA backend.
bool isGpuSchedulingToggle(const std::string& name);

}  // namespace pt
