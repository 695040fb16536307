#pragma once
// Error against run time: a curve of measurements of a progressive render against a reference
// (relMSE, RMSE, MAPE: image_error.h), and what its tail says about convergence. Both
// `pt-render converge` and the editor's live plot (editor/error_tracker.h) read curves through
// these functions, so they judge alike.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/util/image_error.h"

namespace pt {

struct ErrorPoint {
    double seconds = 0.0;  // render time since the accumulation (re)started
    uint32_t spp = 0;
    ImageError error;
};

// Least-squares slope of log relMSE against log time over the last decade of time (all points
// when less than a decade was measured). An unbiased estimator's relMSE falls as 1/time
// (slope -1) until it meets the reference's own noise, which is subtracted first.
struct TailSlope {
    double slope = 0.0;
    double decades = 0.0;  // the span of time the fit covers, in decades: 1, or less when less was measured
    size_t points = 0;
    bool exact = false;  // the last error is 0: nothing left to fall (e.g. a zero-variance estimator)
};
TailSlope fitTailSlope(const std::vector<ErrorPoint>& points, double referenceNoiseRelMse);

// Shallower than this over the last decade: the error has stopped falling.
constexpr double kStuckSlope = -0.8;
bool biasedOrStuck(const TailSlope& fit);

// The relMSE, RMSE and MAPE of a curve at `seconds`, interpolated in log-log between the
// points around it (the first or last point outside them).
ImageError errorAt(const std::vector<ErrorPoint>& points, double seconds);

}  // namespace pt
