#pragma once
// A --variant of `pt-render converge`: "NAME" (the default toggles) or
// "NAME:KEY=VALUE,KEY=VALUE". Keys are the toggle names of stats and the editor
// (render/backend/toggle_states.h): nee, mis, rr, bvh, pixel_jitter, megakernel, compaction,
// material_sort, first_hit_cache take on/off; clamp and rebuild_ratio take a number. Each
// key is turned into the render command's flag and read by parseToggles, so a variant means
// exactly what the same flags mean to `pt-render render`. denoise=on measures the error of
// the denoised image (render --denoise) instead of the raw one; with it, guide_samples=N|all
// (render --guide-samples) caps its guides.
#include <string>
#include <vector>

#include "render/backend/backend.h"

namespace pt::cli {

struct ConvergeVariant {
    std::string name;
    std::string spec;  // as given, for reports
    IntegratorToggles toggles;
    bool denoise = false;
    uint32_t guideSamples = kSettledGuideSamples;  // 0: the guides take every sample
};

// Throws UsageError naming the spec and the bad key or value.
ConvergeVariant parseVariant(const std::string& spec);

}  // namespace pt::cli
