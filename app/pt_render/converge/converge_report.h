#pragma once
// What `pt-render converge` makes of the measured curves: the CSV, the equal-time table and
// the verdict on each variant's rate of convergence.
#include <cstdio>
#include <string>
#include <vector>

#include "pt_render/converge/converge_run.h"

namespace pt::cli {

struct VariantCurve {
    std::string name;
    std::vector<ErrorPoint> points;  // ascending time
};

// variant,seconds,spp,relmse,rmse,mape (MAPE in percent), one row a point.
std::string convergeCsv(const std::vector<VariantCurve>& curves);

// The equal-time table (each variant at the longest time all reached, and its ratio to the
// best) and the verdicts, as printed at the end of a run.
void printConvergeSummary(std::FILE* out, const std::vector<VariantCurve>& curves,
                          double referenceNoiseRelMse);

}  // namespace pt::cli
