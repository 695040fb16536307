#include "pt_render/converge/converge_run.h"

#include <algorithm>
#include <cmath>

namespace pt::cli {

std::vector<double> logSpacedTimes(double budget) {
    constexpr int kPerDecade = 4;
    const double earliest = std::max(budget / 1000.0, 0.01);
    std::vector<double> times;
    for (int i = 0;; ++i) {
        const double t = budget * std::pow(10.0, -double(i) / kPerDecade);
        if (t < earliest * 0.999 && !times.empty()) break;
        times.push_back(t);
    }
    std::reverse(times.begin(), times.end());
    return times;
}

std::vector<ErrorPoint> measureConvergence(Backend& backend, const std::vector<float>& reference,
                                           double budget, bool denoise, const ProgressFn& progress,
                                           const std::function<bool()>& stop) {
    const std::vector<double> times = logSpacedTimes(budget);
    std::vector<ErrorPoint> points;
    std::vector<float> image;
    double secondsPerPass = 0.0;  // unknown until the first pass
    size_t next = 0;
    while (next < times.size() && !(stop && stop())) {
        const BackendStats stats = backend.stats();
        if (stats.samplesPerPixel > 0 && stats.renderSeconds >= times[next]) {
            if (denoise) {
                backend.readDenoised(image);
            } else {
                backend.readBeauty(image);
            }
            points.push_back({stats.renderSeconds, stats.samplesPerPixel, imageError(image, reference)});
            while (next < times.size() && times[next] <= stats.renderSeconds) ++next;
            continue;
        }
        // Aim to end the batch just at the next time; one pass at first, to learn its cost.
        const double passes =
            secondsPerPass > 0.0 ? std::ceil((times[next] - stats.renderSeconds) / secondsPerPass) : 1.0;
        const uint32_t n = uint32_t(std::clamp(passes, 1.0, 65536.0));
        backend.render(n);
        secondsPerPass = std::max((backend.stats().renderSeconds - stats.renderSeconds) / n, 1e-7);
        reportProgress(progress, "converge", std::min(backend.stats().renderSeconds / budget, 1.0));
    }
    return points;
}

}  // namespace pt::cli
