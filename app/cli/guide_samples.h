#pragma once
// --guide-samples N|all (render) and guide_samples=N|all (converge variants): how many samples
// the denoiser's guides accumulate before they stop (Backend::setAovSampleCap); by default
// kSettledGuideSamples, "all" to record them with every sample of the beauty.
#include <cstdint>

#include "cli/cli_options.h"
#include "render/backend/backend.h"

namespace pt::cli {

// The value of --guide-samples in `o`: kSettledGuideSamples where it is absent, 0 (settledGuideCap's
// "no cap") for "all"; throws UsageError unless it is "all" or a positive integer.
uint32_t guideSamplesOption(const Options& o);

}  // namespace pt::cli
