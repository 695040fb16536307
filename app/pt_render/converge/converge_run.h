#pragma once
// Rendering one variant progressively and measuring its error against the reference at
// log-spaced times. Time is the backend's render time (BackendStats::renderSeconds): the
// readbacks and error sums in between are not charged to the variant.
#include <cstdint>
#include <functional>
#include <vector>

#include "render/backend/backend.h"
#include "render/util/error_curve.h"
#include "render/util/progress.h"

namespace pt::cli {

// Four times a decade, down from `budget` to budget / 1000 (but not below 10 ms), ascending.
std::vector<double> logSpacedTimes(double budget);

// Renders on `backend` (synced, with the variant's toggles) until `budget` seconds, recording
// a point at the first pass that ends at or past each of logSpacedTimes(budget): the error of
// the beauty, or with `denoise` of the denoised beauty (the backend accumulating the guides;
// the filter's own time is not render time). Where `stop` (polled between batches of passes)
// says so, it returns the points recorded so far.
std::vector<ErrorPoint> measureConvergence(Backend& backend, const std::vector<float>& reference,
                                           double budget, bool denoise, const ProgressFn& progress,
                                           const std::function<bool()>& stop = {});

}  // namespace pt::cli
