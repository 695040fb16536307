#include "render/util/error_curve.h"

#include <algorithm>
#include <cmath>

namespace pt {

TailSlope fitTailSlope(const std::vector<ErrorPoint>& points, double referenceNoiseRelMse) {
    TailSlope fit;
    if (points.empty()) return fit;
    const double last = points.back().seconds;
    fit.exact = points.back().error.relMse <= 0.0;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const ErrorPoint& p : points) {
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

ImageError errorAt(const std::vector<ErrorPoint>& points, double seconds) {
    if (points.empty()) return {};
    if (seconds <= points.front().seconds) return points.front().error;
    for (size_t i = 1; i < points.size(); ++i) {
        const ErrorPoint &a = points[i - 1], &b = points[i];
        if (seconds > b.seconds) continue;
        const double t = std::log(seconds / a.seconds) / std::log(b.seconds / a.seconds);
        const auto lerp = [t](double x, double y) {
            return x > 0 && y > 0 ? std::exp(std::log(x) + t * (std::log(y) - std::log(x))) : x + t * (y - x);
        };
        return {lerp(a.error.relMse, b.error.relMse), lerp(a.error.rmse, b.error.rmse),
                lerp(a.error.mape, b.error.mape)};
    }
    return points.back().error;
}

}  // namespace pt
