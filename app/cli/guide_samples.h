#pragma once
// --guide-samples N|all (render) and guide_samples=N|all (converge variants): how many samples
// the denoiser's guides accumulate before they stop (Backend::setAovSampleCap); by default
// kSettledGuideSamples, "all" to record them with every sample of the beauty.
#include <cstdint>
#include <string>

#include "render/backend/backend.h"

namespace pt::cli {

// 0 for "all" (settledGuideCap's "no cap"); throws UsageError (naming `flag`) unless `value` is "all" or a
// positive integer.
uint32_t parseGuideSamples(const std::string& flag, const std::string& value);

}  // namespace pt::cli
