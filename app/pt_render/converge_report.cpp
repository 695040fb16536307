#include "converge_report.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "output_paths.h"

namespace pt::cli {

std::string convergeCsv(const std::vector<VariantCurve>& curves) {
    std::string csv = "variant,seconds,spp,relmse,rmse,mape\n";
    for (const VariantCurve& curve : curves) {
        for (const ConvergePoint& p : curve.points) {
            csv += curve.name + "," + formatFigure(p.seconds) + "," + std::to_string(p.spp) + "," +
                   formatFigure(p.error.relMse) + "," + formatFigure(p.error.rmse) + "," + formatFigure(p.error.mape) +
                   "\n";
        }
    }
    return csv;
}

TailSlope fitTailSlope(const std::vector<ConvergePoint>& points, double referenceNoiseRelMse) {
    TailSlope fit;
    if (points.empty()) return fit;
    const double last = points.back().seconds;
    fit.exact = points.back().error.relMse <= 0.0;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const ConvergePoint& p : points) {
        if (p.seconds < last / 10.0 || p.seconds <= 0.0) continue;
        // The reference's noise adds to every measurement alike; a small share is kept so that
        // a floor estimated too high cannot drive the logarithm to minus infinity.
        const double relMse = std::max(p.error.relMse - referenceNoiseRelMse, 0.05 * p.error.relMse);
        const double x = std::log10(p.seconds), y = std::log10(std::max(relMse, 1e-300));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        ++fit.points;
    }
    fit.decades = std::min(std::log10(last / points.front().seconds), 1.0);
    const double n = double(fit.points), denominator = n * sxx - sx * sx;
    fit.slope = fit.points >= 2 && denominator > 0 ? (n * sxy - sx * sy) / denominator : 0.0;
    return fit;
}

bool biasedOrStuck(const TailSlope& fit) { return !fit.exact && fit.points >= 3 && fit.slope > kStuckSlope; }

ImageError errorAt(const std::vector<ConvergePoint>& points, double seconds) {
    if (points.empty()) return {};
    if (seconds <= points.front().seconds) return points.front().error;
    for (size_t i = 1; i < points.size(); ++i) {
        const ConvergePoint &a = points[i - 1], &b = points[i];
        if (seconds > b.seconds) continue;
        const double t = std::log(seconds / a.seconds) / std::log(b.seconds / a.seconds);
        const auto lerp = [t](double x, double y) {
            return x > 0 && y > 0 ? std::exp(std::log(x) + t * (std::log(y) - std::log(x))) : x + t * (y - x);
        };
        return {lerp(a.error.relMse, b.error.relMse), lerp(a.error.rmse, b.error.rmse), lerp(a.error.mape, b.error.mape)};
    }
    return points.back().error;
}

namespace {

std::string verdict(const TailSlope& fit) {
    char text[128];
    if (fit.exact) {
        std::snprintf(text, sizeof text, "exact (zero error)");
    } else if (fit.points < 3) {
        std::snprintf(text, sizeof text, "too few points to judge (%zu)", fit.points);
    } else {
        std::snprintf(text, sizeof text, "%s (slope %.2f over %s)", biasedOrStuck(fit) ? "BIASED OR STUCK" : "converging",
                      fit.slope, fit.decades >= 0.999 ? "the last decade" : "less than a decade, all there is");
    }
    return text;
}

}  // namespace

void printConvergeSummary(std::FILE* out, const std::vector<VariantCurve>& curves, double referenceNoiseRelMse) {
    double equalTime = std::numeric_limits<double>::infinity();
    for (const VariantCurve& c : curves) {
        if (!c.points.empty()) equalTime = std::min(equalTime, c.points.back().seconds);
    }
    if (!std::isfinite(equalTime)) return;
    double best = std::numeric_limits<double>::infinity();
    for (const VariantCurve& c : curves) best = std::min(best, errorAt(c.points, equalTime).relMse);
    std::fprintf(out, "equal time: %.3g s, the longest time every variant reached\n", equalTime);
    if (referenceNoiseRelMse > 0) std::fprintf(out, "reference noise (relMSE): %.3g\n", referenceNoiseRelMse);
    std::fprintf(out, "%-16s %8s %12s %12s %10s %8s  %s\n", "variant", "spp", "relMSE", "RMSE", "MAPE %", "x best",
                 "convergence");
    for (const VariantCurve& c : curves) {
        const ImageError e = errorAt(c.points, equalTime);
        const auto reached = std::find_if(c.points.begin(), c.points.end(),
                                          [&](const ConvergePoint& p) { return p.seconds >= equalTime; });
        const uint32_t spp = reached != c.points.end() ? reached->spp : 0;
        std::fprintf(out, "%-16s %8u %12.4g %12.4g %10.3g %8.2f  %s\n", c.name.c_str(), spp, e.relMse, e.rmse, e.mape,
                     best > 0 ? e.relMse / best : 1.0, verdict(fitTailSlope(c.points, referenceNoiseRelMse)).c_str());
    }
}

}  // namespace pt::cli
