#pragma once
// What `pt-render converge` makes of the measured curves: the CSV, the equal-time table and
// the verdict on each variant's rate of convergence.
#include <cstdio>
#include <string>
#include <vector>

#include "converge_run.h"

namespace pt::cli {

struct VariantCurve {
    std::string name;
    std::vector<ConvergePoint> points;  // ascending time
};

// variant,seconds,spp,relmse,rmse,mape (MAPE in percent), one row a point.
std::string convergeCsv(const std::vector<VariantCurve>& curves);

// Least-squares slope of log relMSE against log time over the last decade of time (all points
// when less than a decade was measured). An unbiased estimator's relMSE falls as 1/time
// (slope -1) until it meets the reference's own noise, which is subtracted first.
struct TailSlope {
    double slope = 0.0;
    double decades = 0.0;  // the span of time the fit covers, in decades: 1, or less when less was measured
    size_t points = 0;
    bool exact = false;    // the last error is 0: nothing left to fall (e.g. a zero-variance estimator)
};
TailSlope fitTailSlope(const std::vector<ConvergePoint>& points, double referenceNoiseRelMse);

// Shallower than this over the last decade: the error has stopped falling.
constexpr double kStuckSlope = -0.8;
bool biasedOrStuck(const TailSlope& fit);

// The relMSE, RMSE and MAPE of a curve at `seconds`, interpolated in log-log between the
// points around it (the first or last point outside them).
ImageError errorAt(const std::vector<ConvergePoint>& points, double seconds);

// The equal-time table (each variant at the longest time all reached, and its ratio to the
// best) and the verdicts, as printed at the end of a run.
void printConvergeSummary(std::FILE* out, const std::vector<VariantCurve>& curves, double referenceNoiseRelMse);

}  // namespace pt::cli
