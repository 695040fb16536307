#include "pt_render/converge/converge_report.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cli/output_paths.h"

namespace pt::cli {

std::string convergeCsv(const std::vector<VariantCurve>& curves) {
    std::string csv = "variant,seconds,spp,relmse,rmse,mape\n";
    for (const VariantCurve& curve : curves) {
        for (const ErrorPoint& p : curve.points) {
            csv += curve.name + "," + formatFigure(p.seconds) + "," + std::to_string(p.spp) + "," +
                   formatFigure(p.error.relMse) + "," + formatFigure(p.error.rmse) + "," +
                   formatFigure(p.error.mape) + "\n";
        }
    }
    return csv;
}

namespace {

std::string verdict(const TailSlope& fit) {
    char text[128];
    if (fit.exact) {
        std::snprintf(text, sizeof text, "exact (zero error)");
    } else if (fit.points < 3) {
        std::snprintf(text, sizeof text, "too few points to judge (%zu)", fit.points);
    } else {
        std::snprintf(text, sizeof text, "%s (slope %.2f over %s)",
                      biasedOrStuck(fit) ? "BIASED OR STUCK" : "converging", fit.slope,
                      fit.decades >= 0.999 ? "the last decade" : "less than a decade, all there is");
    }
    return text;
}

}  // namespace

void printConvergeSummary(std::FILE* out, const std::vector<VariantCurve>& curves,
                          double referenceNoiseRelMse) {
    double equalTime = std::numeric_limits<double>::infinity();
    for (const VariantCurve& c : curves) {
        if (!c.points.empty()) equalTime = std::min(equalTime, c.points.back().seconds);
    }
    if (!std::isfinite(equalTime)) return;
    double best = std::numeric_limits<double>::infinity();
    for (const VariantCurve& c : curves) best = std::min(best, errorAt(c.points, equalTime).relMse);
    std::fprintf(out, "equal time: %.3g s, the longest time every variant reached\n", equalTime);
    if (referenceNoiseRelMse > 0) std::fprintf(out, "reference noise (relMSE): %.3g\n", referenceNoiseRelMse);
    std::fprintf(out, "%-16s %8s %12s %12s %10s %8s  %s\n", "variant", "spp", "relMSE", "RMSE", "MAPE %",
                 "x best", "convergence");
    for (const VariantCurve& c : curves) {
        const ImageError e = errorAt(c.points, equalTime);
        const auto reached = std::find_if(c.points.begin(), c.points.end(),
                                          [&](const ErrorPoint& p) { return p.seconds >= equalTime; });
        const uint32_t spp = reached != c.points.end() ? reached->spp : 0;
        std::fprintf(out, "%-16s %8u %12.4g %12.4g %10.3g %8.2f  %s\n", c.name.c_str(), spp, e.relMse, e.rmse,
                     e.mape, best > 0 ? e.relMse / best : 1.0,
                     verdict(fitTailSlope(c.points, referenceNoiseRelMse)).c_str());
    }
}

}  // namespace pt::cli
